#include "tagmap/image_variants.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace tagmap
{
std::vector<ImageVariant> makeImageVariants(const cv::Mat& gray, const std::vector<std::string>& names)
{
	const std::vector<std::string> order = names.empty() ? std::vector<std::string>{"raw", "otsu", "half"} : names;
	std::vector<ImageVariant> out;
	for (const auto& name : order)
	{
		ImageVariant v;
		v.name = name;
		if (name == "raw")
			v.gray = gray;
		else if (name == "otsu")
			cv::threshold(gray, v.gray, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
		else if (name == "half" && std::min(gray.cols, gray.rows) >= 64)
		{
			cv::resize(gray, v.gray, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
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
