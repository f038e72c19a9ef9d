#include "tagmap/front_side.h"

#include <algorithm>
#include <cmath>

namespace tagmap
{
namespace
{
/** A line of sight ends this far short of its viewpoint: the sensor's own
 *  housing and mount may have left points around it. */
constexpr double kSensorClearance = 0.3;

// How far along a -> b (0..1) the segment stays within the grid's points'
// bounds grown by a voxel: beyond, no voxel is occupied.
double withinGrid(const VoxelGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	const Eigen::Vector3d lo = grid.lowerBound().array() - grid.cellSize(), hi = grid.upperBound().array() + grid.cellSize();
	double t = 1;
	for (int axis = 0; axis < 3; axis++)
	{
		const double d = b[axis] - a[axis];
		if (d > 0 && b[axis] > hi[axis]) t = std::min(t, std::max(0.0, (hi[axis] - a[axis]) / d));
		if (d < 0 && b[axis] < lo[axis]) t = std::min(t, std::max(0.0, (lo[axis] - a[axis]) / d));
	}
	return t;
}

// Whether the segment a -> b crosses no occupied voxel: sampled every
// quarter voxel, so a voxel it crosses for more than that is met (a wall's
// sheet of voxels is at least a voxel deep along any line through it).
// Only the part within the map is walked: a sensor position far outside
// it (or a trajectory in another frame, kilometres off) costs nothing.
bool lineIsClear(const VoxelGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	const Eigen::Vector3d d = b - a;
	const double length = d.norm(), step = 0.25 * grid.cellSize(), walked = withinGrid(grid, a, b) * length;
	VoxelKey last = grid.keyOf(a.cast<float>());
	if (grid.find(last) >= 0) return false;
	for (double s = step; s < walked; s += step)
	{
		const VoxelKey k = grid.keyOf((a + d * (s / length)).cast<float>());
		if (k == last) continue;
		last = k;
		if (grid.find(k) >= 0) return false;
	}
	return true;
}

// Whether a line from `from` to one of the viewpoints on the side `normal`
// points to is clear; the nearest are tried first, and the first clear one
// answers.
bool seenFrom(const Eigen::Vector3d& from, const Eigen::Vector3d& normal, const std::vector<Eigen::Vector3d>& viewpoints,
			  const VoxelGrid& grid)
{
	std::vector<std::pair<double, size_t>> onSide;
	for (size_t k = 0; k < viewpoints.size(); k++)
	{
		const Eigen::Vector3d to = viewpoints[k] - from;
		if (to.dot(normal) > 0 && to.norm() > kSensorClearance) onSide.emplace_back(to.norm(), k);
	}
	std::sort(onSide.begin(), onSide.end());
	for (const auto& [distance, k] : onSide)
		if (lineIsClear(grid, from, from + (viewpoints[k] - from) * (1 - kSensorClearance / distance))) return true;
	return false;
}
}  // namespace

FrontSideEvidence measureFrontSide(const TagDetection& t, const std::vector<uint32_t>& around, const float* xs,
								   const float* ys, const float* zs, double surface, const FrontSideParams& p)
{
	FrontSideEvidence e;
	const int n = std::max(1, p.columns);
	const double inner = 0.8 * t.size, depth = p.depthSizes * t.size;
	if (!(inner > 0) || !(depth > surface)) return e;
	std::vector<char> front(static_cast<size_t>(n * n), 0), back(front.size(), 0);
	const Eigen::Isometry3d toTag = t.pose.inverse();
	for (uint32_t i : around)
	{
		const Eigen::Vector3d q = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		const double d = std::abs(q.z());
		if (d <= surface || d > depth) continue;
		const int cx = static_cast<int>(std::floor((q.x() / inner + 0.5) * n));
		const int cy = static_cast<int>(std::floor((q.y() / inner + 0.5) * n));
		if (cx < 0 || cy < 0 || cx >= n || cy >= n) continue;
		(q.z() > 0 ? front : back)[static_cast<size_t>(cy * n + cx)] = 1;
	}
	const double cells = static_cast<double>(front.size());
	e.blockedInFront = static_cast<double>(std::count(front.begin(), front.end(), 1)) / cells;
	e.blockedBehind = static_cast<double>(std::count(back.begin(), back.end(), 1)) / cells;
	return e;
}

bool printedFaceLooksIntoSolid(const FrontSideEvidence& e, const FrontSideParams& p)
{
	return p.enabled && e.blockedInFront >= p.blockedFraction && e.blockedBehind <= p.freeFraction;
}

bool seenOnlyFromBehind(const TagDetection& t, const std::vector<Eigen::Vector3d>& viewpoints, const VoxelGrid& grid,
						double clearance)
{
	if (viewpoints.empty()) return false;
	const Eigen::Vector3d c = t.position(), n = t.pose.linear().col(2);
	return !seenFrom(c + clearance * n, n, viewpoints, grid) && seenFrom(c - clearance * n, -n, viewpoints, grid);
}

}  // namespace tagmap
