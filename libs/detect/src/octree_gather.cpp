#include "tagmap/octree_gather.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tagmap/parallel.h"

namespace tagmap
{
namespace
{
/** `v` sorted ascending, as std::sort would, in three counting passes of
 *  11 bits: a gather returns tens of thousands of indices in runs (voxel by
 *  voxel), where a comparison sort was a sixth of the decode stage. */
void radixSort(std::vector<uint32_t>& v)
{
	if (v.size() < 256)
	{
		std::sort(v.begin(), v.end());
		return;
	}
	std::vector<uint32_t> tmp(v.size());
	for (int shift = 0; shift < 32; shift += 11)
	{
		size_t count[2049] = {};
		for (uint32_t x : v) count[((x >> shift) & 2047) + 1]++;
		if (count[((v[0] >> shift) & 2047) + 1] == v.size()) continue;  // one bucket: nothing to move
		for (size_t b = 1; b < 2049; b++) count[b] += count[b - 1];
		for (uint32_t x : v) tmp[count[(x >> shift) & 2047]++] = x;
		v.swap(tmp);
	}
}
}  // namespace

OctreeGatherer::OctreeGatherer(const VoxelGrid& grid, double leaf, const GatherParams& p, unsigned threads)
	: grid_(grid), params_(p)
{
	// A leaf finer than a voxel would only mark voxel centres: the gather
	// below visits the voxels under each occupied leaf.
	if (!(leaf >= grid.cellSize())) throw std::invalid_argument("octree leaf must be at least the voxel cell");
	// A small map (a single scan: 10-50 k points) is searched voxel row by
	// voxel row: its boxes span few rows, and building the tree would cost
	// more than every gather it speeds up. The points found are the same.
	if (grid.voxelCount() < kTreeFromVoxels) return;
	tree_ = std::make_unique<octomap::OcTree>(leaf);
	// Only occupancy matters: mark each occupied leaf once (a leaf holds
	// several voxels; repeated hits only raise its log-odds),
	// then let OctoMap fill in the inner nodes.
	threads = grid.voxelCount() < 65536 ? 1u : resolveThreads(threads);
	std::vector<std::vector<uint64_t>> parts(threads);
	parallelForChunks(grid.voxelCount(), threads, [&](unsigned c, size_t b, size_t e) {
		std::vector<uint64_t>& part = parts[c];
		for (size_t v = b; v < e; v++)
		{
			const Eigen::Vector3d m = grid.voxelCenter(grid.keyOfVoxel(v));
			octomap::OcTreeKey k;
			if (!tree_->coordToKeyChecked(octomap::point3d(m.x(), m.y(), m.z()), k)) continue;
			const uint64_t packed = k[0] | (uint64_t{k[1]} << 16) | (uint64_t{k[2]} << 32);
			if (part.empty() || part.back() != packed) part.push_back(packed);  // runs along x share a leaf
		}
	});
	std::vector<uint64_t> leaves;
	for (auto& part : parts)
	{
		leaves.insert(leaves.end(), part.begin(), part.end());
		part = {};
	}
	std::sort(leaves.begin(), leaves.end());
	leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
	for (uint64_t packed : leaves)
	{
		const octomap::OcTreeKey k(static_cast<octomap::key_type>(packed & 0xffff),
								   static_cast<octomap::key_type>((packed >> 16) & 0xffff),
								   static_cast<octomap::key_type>(packed >> 32));
		tree_->updateNode(k, true, true);
	}
	tree_->updateInnerOccupancy();
	leaves_ = tree_->getNumLeafNodes();
}

OctreeGatherer::~OctreeGatherer() = default;

std::vector<uint32_t> OctreeGatherer::gather(const OrientedBox& box, double spacing, const float* xs,
											 const float* ys, const float* zs) const
{
	const Eigen::Vector3d half(0.5 * box.extent.x() * params_.enlarge, 0.5 * box.extent.y() * params_.enlarge,
							   0.5 * box.extent.z() + params_.slabSpacings * spacing);
	// Axis-aligned bounds of the enlarged box, for the octree query.
	const Eigen::Vector3d reach = box.axes.cwiseAbs() * half;
	const Eigen::Vector3d lo = box.center - reach, hi = box.center + reach;
	const double cell = grid_.cellSize();
	// The rows of voxels within [a, b] (clipped to the query bounds).
	std::vector<VoxelGrid::KeySpan> spans;
	const auto addBlock = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
		const Eigen::Vector3d qa = a.cwiseMax(lo), qb = b.cwiseMin(hi);
		const VoxelKey ka = grid_.keyOf((qa.array() + cell * 1e-6).matrix().cast<float>());
		const VoxelKey kb = grid_.keyOf((qb.array() - cell * 1e-6).matrix().cast<float>());
		VoxelGrid::KeySpan r;
		for (int z = ka.z; z <= kb.z; z++)
			for (int y = ka.y; y <= kb.y; y++)
				if (grid_.rowSpan(ka.x, kb.x, y, z, r)) spans.push_back(r);
	};
	if (!tree_) addBlock(lo, hi);
	else
		for (auto it = tree_->begin_leafs_bbx(octomap::point3d(lo.x(), lo.y(), lo.z()),
											 octomap::point3d(hi.x(), hi.y(), hi.z())),
				  end = tree_->end_leafs_bbx();
			 it != end; ++it)
		{
			if (!tree_->isNodeOccupied(*it)) continue;
			// Neighbour-grid voxels under this leaf.
			const Eigen::Vector3d c(it.getX(), it.getY(), it.getZ());
			addBlock(c.array() - it.getSize() / 2, c.array() + it.getSize() / 2);
		}
	// All the leaves' rows at once: side by side along x they join, and one
	// cursor moving forward visits their voxels (forEachVoxelInSpans).
	std::vector<uint32_t> out;
	grid_.forEachVoxelInSpans(std::move(spans), [&](size_t v) {
		for (const uint32_t* p = grid_.begin(v); p != grid_.end(v); ++p)
		{
			const Eigen::Vector3d q = box.axes.transpose() * (Eigen::Vector3d(xs[*p], ys[*p], zs[*p]) - box.center);
			if (std::abs(q.x()) <= half.x() && std::abs(q.y()) <= half.y() && std::abs(q.z()) <= half.z())
				out.push_back(*p);
		}
	});
	radixSort(out);  // each voxel was visited once: no point twice
	return out;
}

}  // namespace tagmap
