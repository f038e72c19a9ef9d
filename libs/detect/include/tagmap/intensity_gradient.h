// Stage 1 (paper, Sec. II-B): keep the points where intensity changes fast.
// For each point, a linear model I(x) = A^T x + b is fitted by least squares
// to its neighbours within radius r (b = their mean intensity); the point is
// kept when |A| is high. Tags are black-on-white, so their borders and bits
// survive while plain walls, floors and cars are dropped.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tagmap/count_progress.h"
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
	/** A kept point's linear fit must explain at least this fraction of the
	 *  intensity variance around it (R^2): edges do, noise and points of a
	 *  surface merged from viewpoints at different ranges do not. */
	double minExplained = 0.3;
	/** Radius levels (1x, 3x, 9x ...) for points too sparse at the finer
	 *  one; 1 disables the sparse levels. */
	int densityLevels = 3;
};

struct IntensityGradientResult
{
	std::vector<uint32_t> keptPoints;  // indices into the map, ascending
	/** Per kept point, how far its slope clears the bar: |A| / cut in
	 *  steps of 1 / kStrengthSteps (kStrengthSteps at the bar, at most 63).
	 *  Where a whole surface clears the bar (intensity stripes of a map
	 *  merged from many ranges, strong noise) a tag's edges clear it by
	 *  more; splitClusters() uses it. */
	std::vector<uint8_t> keptStrength;
	static constexpr int kStrengthSteps = 8;
	/** The raised bar, 2.25 x the plain one: a slope of 0.675 of the map's
	 *  intensity spread across r, where an ideal black-white edge gives
	 *  0.85 x its contrast. Ink on paper is about the widest contrast a map
	 *  has; stripes of a surface merged from many ranges, or noise, that
	 *  clear the plain bar over a whole wall rarely clear this one. */
	static constexpr int kRaisedStrength = 18;
	double intensitySpread = 0;  // p95 - p5 of the map's intensities
	/** Points with fewer than minNeighbours within r: the map is sparser
	 *  there than its median (far from the sensor, a fast pass). The
	 *  pipeline runs them again at a larger radius. */
	std::vector<uint32_t> sparsePoints;
	/** The kept points whose fit pure noise would match with this many
	 *  neighbours, 1 time in 1000 (ascending; a subset of keptPoints). With
	 *  range noise thicker than r (2 cm on a dense scan) or strong
	 *  intensity noise, a plain wall passes the fixed bars and clusters
	 *  with the tag on it into one box metres wide; without these points
	 *  the tag's own edges stand apart (splitClusters). */
	std::vector<uint32_t> keptByChance;
};

/** `radius`: the neighbourhood r (DerivedLengths::gradientRadius); `grid`
 *  must have been built over the same points with cells of at least r, so
 *  that a point's neighbours lie in its voxel's 3x3x3 block (throws
 *  std::invalid_argument otherwise). `spread`: the intensity spread to normalise by (0: measure it on these points).
 *  `progress`: points examined so far and in all, from the worker threads. */
IntensityGradientResult filterByIntensityGradient(const float* xs, const float* ys, const float* zs, const float* is,
												  const VoxelGrid& grid, double radius, const IntensityGradientParams& p,
												  unsigned threads, double spread = 0,
												  const CountProgressFn& progress = {});

/** The slope fitted at one point: its norm, how much of the intensity
 *  variance it explains, and along how many directions it was fitted. */
struct SurfaceSlope
{
	double norm = 0;  // |A|
	double explained = 0;  // variance of A^T x: the part of var(I) the slope explains
	int directions = 0;  // how many directions the slope was fitted along (2 on a surface)
};

/** The least-squares slope A = C^-1 c from the neighbours' position
 *  covariance C and their position-intensity covariance c, solved along
 *  C's principal directions that spread at least a quarter as much as the
 *  widest (along a surface, not its noise-thin normal). */
SurfaceSlope surfaceSlope(const Eigen::Matrix3d& C, const Eigen::Vector3d& c);

/** An upper bound of surfaceSlope(C, c).norm, without the eigen-solve. */
double slopeBound(const Eigen::Matrix3d& C, const Eigen::Vector3d& c);

/** Robust intensity range p95 - p5 (from a strided sample; deterministic). */
double robustIntensitySpread(const float* is, size_t n);

}  // namespace tagmap
