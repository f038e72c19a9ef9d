// Stage 0: how far apart the map's points are. Every length the pipeline
// uses (gradient neighbourhood, cluster tolerance, image pixel) is a
// multiple of this, so one parameter set works for a sparse SLAM map and a
// dense terrestrial scan alike.
#pragma once

#include <cstddef>

namespace tagmap
{
struct PointSpacingParams
{
	size_t samples = 2000;  // points whose nearest neighbour is measured
};

/** Median nearest-neighbour distance of `p.samples` evenly strided points
 *  (exact: found among all n points), 0 if fewer than 2 points. One or two
 *  passes over the map with `threads` threads (0: all cores; the result
 *  does not depend on it). */
double estimatePointSpacing(const float* xs, const float* ys, const float* zs, size_t n, const PointSpacingParams& p = {},
							unsigned threads = 0);

}  // namespace tagmap
