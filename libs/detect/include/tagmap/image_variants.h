// Stage 5b: the same intermediate-plane image, prepared a few ways for the
// decoders. A tag far from the sensor, or blurred by map drift or a wide
// beam footprint, often fails on the smooth image but reads once binarised
// (Otsu) or seen at half resolution (blur shrinks relative to a pixel). A
// dense map's image shows each point's intensity noise and each scan
// line's level as grain and stripes finer than a cell, which break the
// decoders' outlines: the half-size image smoothed over a fifth of a cell
// averages them out (random_023's tagStandard41h12:189, random_216's
// tagCircle49h12:40 read only there).
// Variants are tried in order until one yields a verified tag.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace tagmap
{
struct ImageVariant
{
	std::string name;  // "raw", "otsu", "half", "half_smooth"
	cv::Mat gray;  // CV_8UC1, continuous
	double scale = 1;  // variant pixel = scale x original pixels
};

/** Variants in the order they should be tried. `names` selects and orders
 *  them (unknown names are ignored); empty means all. */
std::vector<ImageVariant> makeImageVariants(const cv::Mat& gray, const std::vector<std::string>& names = {});

}  // namespace tagmap
