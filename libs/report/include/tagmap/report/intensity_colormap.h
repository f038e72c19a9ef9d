// Intensity to colour for the report's pictures. Intensities are normalised
// between two percentiles, not min/max: one retro-reflector at 100x the
// paper's return would otherwise turn the whole map black.
#pragma once

#include <opencv2/core.hpp>

#include <cstddef>

namespace tagmap::report
{
struct IntensityRange
{
	float lo = 0, hi = 1;
};

/** The `loPercent`..`hiPercent` percentiles of `n` values (NaNs ignored),
 *  from at most ~1 M evenly strided samples so huge maps stay fast. */
IntensityRange percentileRange(const float* values, size_t n, double loPercent = 2, double hiPercent = 98);

/** CV_32FC1 `values` -> CV_8UC3 BGR through `colormap` (cv::COLORMAP_*);
 *  pixels where `mask` (CV_8UC1) is 0 get `background`. */
cv::Mat colorize(const cv::Mat& values, const cv::Mat& mask, IntensityRange range, int colormap,
				 const cv::Scalar& background);

}  // namespace tagmap::report
