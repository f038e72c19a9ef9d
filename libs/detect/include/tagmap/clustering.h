// Stage 2 (paper, Sec. II-C): Euclidean clustering of the kept points
// (Rusu 2009) and an oriented bounding box per cluster from PCA. The white
// paper margin around a tag leaves a gap with no gradient, so a tag's edge
// points come out as one cluster of their own.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tagmap
{
struct ClusteringParams
{
	/** Points closer than tolerance = toleranceSpacings * spacing are joined
	 *  (on a voxel grid, so up to ~1.7 x that across a voxel diagonal). */
	double toleranceSpacings = 3.0;
	size_t minPoints = 20;  // fewer: noise, not a tag
	/** Tolerance multipliers tried (multi-scale clustering: addClusters in candidate_proposals.cpp). */
	std::vector<double> scales = {1.0, 3.0};
};

/** Oriented bounding box: axes are the PCA directions, largest first. */
struct OrientedBox
{
	Eigen::Vector3d center = Eigen::Vector3d::Zero();
	Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: length, width, height directions
	Eigen::Vector3d extent = Eigen::Vector3d::Zero();  // l >= w >= h (full edge lengths)
	/** Robust height: twice the 95th percentile of the points' distances
	 *  from their median along the height axis (0: not measured). The
	 *  extreme points that set extent.z() grow with the number of points
	 *  under range noise (about +-3.7 sigma for 1000 points); this does not. */
	double thickness = 0;
};

struct Cluster
{
	std::vector<uint32_t> points;  // map indices
	OrientedBox box;
};

/** Clusters `pointIndices` of the map (sorted by first point index, so the
 *  order is deterministic). */
std::vector<Cluster> clusterPoints(const float* xs, const float* ys, const float* zs,
								   const std::vector<uint32_t>& pointIndices, double tolerance, size_t minPoints);

/** PCA box of the given map points. */
OrientedBox fitOrientedBox(const float* xs, const float* ys, const float* zs, const std::vector<uint32_t>& points);

}  // namespace tagmap
