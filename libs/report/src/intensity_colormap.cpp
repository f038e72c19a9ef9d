#include "tagmap/quantile.h"
#include "tagmap/report/intensity_colormap.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tagmap::report
{
IntensityRange percentileRange(const float* values, size_t n, double loPercent, double hiPercent)
{
	const size_t stride = std::max<size_t>(1, n / 1000000);
	std::vector<float> v;
	v.reserve(n / stride + 1);
	for (size_t i = 0; i < n; i += stride)
		if (std::isfinite(values[i])) v.push_back(values[i]);
	if (v.empty()) return {};
	IntensityRange r{quantileInPlace(v, loPercent / 100.0), quantileInPlace(v, hiPercent / 100.0)};
	if (!(r.hi > r.lo)) r.hi = r.lo + 1;  // constant intensity: one colour, no division by zero
	return r;
}

cv::Mat colorize(const cv::Mat& values, const cv::Mat& mask, IntensityRange range, int colormap,
				 const cv::Scalar& background)
{
	cv::Mat gray;
	const double scale = 255.0 / static_cast<double>(range.hi - range.lo);
	values.convertTo(gray, CV_8U, scale, -static_cast<double>(range.lo) * scale);  // saturates outside the range
	cv::Mat bgr;
	cv::applyColorMap(gray, bgr, colormap);
	bgr.setTo(background, mask == 0);
	return bgr;
}

}  // namespace tagmap::report
