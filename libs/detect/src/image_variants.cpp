#include "tagmap/image_variants.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace tagmap
{
std::vector<ImageVariant> makeImageVariants(const cv::Mat& gray, const std::vector<std::string>& names)
{
	const std::vector<std::string> order =
		names.empty() ? std::vector<std::string>{"raw", "otsu", "half", "half_smooth"} : names;
	std::vector<ImageVariant> out;
	for (const auto& name : order)
	{
		ImageVariant v;
		v.name = name;
		if (name == "raw")
			v.gray = gray;
		else if (name == "otsu")
			cv::threshold(gray, v.gray, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
		else if ((name == "half" || name == "half_smooth") && std::min(gray.cols, gray.rows) >= 64)
		{
			cv::resize(gray, v.gray, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
			// One half-size pixel: a fifth of the smallest cell the images
			// resolve (IntermediatePlaneParams::pixelsPerCell: at most 10
			// pixels a cell, 5 here), so no cell blurs into the next.
			if (name == "half_smooth") cv::GaussianBlur(v.gray, v.gray, cv::Size(), 1.0);
			v.scale = 2;
		}
		else
			continue;
		if (!v.gray.isContinuous()) v.gray = v.gray.clone();
		out.push_back(std::move(v));
	}
	return out;
}

}  // namespace tagmap
