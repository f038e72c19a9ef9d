#include "tagmap/quantile.h"
#include "tagmap/clustering.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "disjoint_sets.h"
#include "tagmap/point_stats.h"
#include "tagmap/voxel_grid.h"

namespace tagmap
{
using detail::DisjointSets;

OrientedBox fitOrientedBox(const float* xs, const float* ys, const float* zs, const std::vector<uint32_t>& points)
{
	OrientedBox box;
	if (points.empty()) return box;
	const PointStats st = pointStats(xs, ys, zs, points);
	const Eigen::Vector3d& mean = st.mean;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(st.scatter);
	// Eigen sorts ascending; we want length, width, height.
	Eigen::Matrix3d axes;
	axes.col(0) = es.eigenvectors().col(2);
	axes.col(1) = es.eigenvectors().col(1);
	axes.col(2) = axes.col(0).cross(axes.col(1));
	Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
	std::vector<double> heights;
	heights.reserve(points.size());
	for (uint32_t i : points)
	{
		const Eigen::Vector3d q = axes.transpose() * (Eigen::Vector3d(xs[i], ys[i], zs[i]) - mean);
		lo = lo.cwiseMin(q);
		hi = hi.cwiseMax(q);
		heights.push_back(q.z());
	}
	box.axes = axes;
	box.extent = hi - lo;
	const double median = quantileInPlace(heights, 0.5);
	for (double& z : heights) z = std::abs(z - median);
	box.thickness = std::min(box.extent.z(), 2 * quantileInPlace(heights, 0.95));
	box.center = mean + axes * (0.5 * (lo + hi));
	return box;
}

std::vector<Cluster> clusterPoints(const float* xs, const float* ys, const float* zs,
								   const std::vector<uint32_t>& pointIndices, double tolerance, size_t minPoints)
{
	std::vector<Cluster> clusters;
	if (pointIndices.empty()) return clusters;
	std::vector<float> kx, ky, kz;
	kx.reserve(pointIndices.size());
	ky.reserve(pointIndices.size());
	kz.reserve(pointIndices.size());
	for (uint32_t i : pointIndices)
	{
		kx.push_back(xs[i]);
		ky.push_back(ys[i]);
		kz.push_back(zs[i]);
	}
	// Voxels of edge `tolerance`, joined with their 26 neighbours: every pair
	// of points closer than the tolerance ends up in one component.
	VoxelGrid grid(kx.data(), ky.data(), kz.data(), kx.size(), tolerance);
	kx = {};
	ky = {};
	kz = {};
	DisjointSets sets(grid.voxelCount());
	std::vector<uint32_t> voxelOf(pointIndices.size());
	VoxelGrid::NeighbourSweep sweep(grid, 0);
	uint32_t block[27];
	for (size_t v = 0; v < grid.voxelCount(); v++)
	{
		const int count = sweep.neighbours(v, block);
		for (int b = 0; b < count; b++)
			if (block[b] > v) sets.unite(static_cast<uint32_t>(v), block[b]);
		for (const uint32_t* p = grid.begin(v); p != grid.end(v); ++p) voxelOf[*p] = static_cast<uint32_t>(v);
	}
	std::vector<int64_t> clusterOfRoot(grid.voxelCount(), -1);
	std::vector<std::vector<uint32_t>> members;
	for (size_t k = 0; k < pointIndices.size(); k++)  // ascending map index: deterministic order
	{
		const uint32_t root = sets.find(voxelOf[k]);
		if (clusterOfRoot[root] < 0)
		{
			clusterOfRoot[root] = static_cast<int64_t>(members.size());
			members.emplace_back();
		}
		members[clusterOfRoot[root]].push_back(pointIndices[k]);
	}
	for (auto& m : members)
	{
		if (m.size() < minPoints) continue;
		Cluster c;
		c.box = fitOrientedBox(xs, ys, zs, m);
		c.points = std::move(m);
		clusters.push_back(std::move(c));
	}
	return clusters;
}

}  // namespace tagmap
