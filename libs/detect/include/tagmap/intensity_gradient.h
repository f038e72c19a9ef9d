// Stage 1 (paper, Sec. II-B): keep the points where intensity changes fast.
// For each point, a linear model I(x) = A^T x + b is fitted by least squares
// to its neighbours within radius r (b = their mean intensity); the point is
// kept when |A| is high. Tags are black-on-white, so their borders and bits
// survive while plain walls, floors and cars are dropped.
#pragma once

#include <cstdint>
#include <vector>

#include "tagmap/voxel_grid.h"

namespace tagmap
{
struct IntensityGradientParams
{
	/** Keep a point when |grad I| * r / spread >= threshold, where spread is
	 *  the map's robust intensity range (5th to 95th percentile). The ratio
	 *  has no unit, so it does not depend on the sensor's intensity scale:
	 *  an ideal black/white edge gives about 0.85 * contrast / spread. */
	double threshold = 0.3;
	/** Fewer neighbours than this: no reliable fit, the point is dropped. */
	int minNeighbours = 6;
};

struct IntensityGradientResult
{
	std::vector<uint32_t> keptPoints;  // indices into the map, ascending
	double intensitySpread = 0;  // p95 - p5 of the map's intensities
};

/** `grid` must have been built over the same points with cell = radius r. */
IntensityGradientResult filterByIntensityGradient(const float* xs, const float* ys, const float* zs, const float* is,
												  const VoxelGrid& grid, const IntensityGradientParams& p,
												  unsigned threads);

/** Robust intensity range p95 - p5 (from a strided sample; deterministic). */
double robustIntensitySpread(const float* is, size_t n);

}  // namespace tagmap
