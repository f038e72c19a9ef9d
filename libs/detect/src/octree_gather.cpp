#include "tagmap/octree_gather.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <array>
#include <climits>
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

/** Along one axis, which voxel keys each leaf index in [kmin, kmax] covers
 *  (its extent clipped to [lo, hi], as a box's bounds clip it), and for
 *  each voxel key the leaf indices that cover it: a contiguous range, as
 *  keys grow with the coordinate. */
struct AxisCover
{
	std::vector<int> first, last;  // per leaf index - kmin
	int keyLo = 0;
	std::vector<std::pair<int, int>> leaves;  // per voxel key - keyLo: leaf indices (- kmin) [a, b]
};

AxisCover coverAlong(const octomap::OcTree& tree, const VoxelGrid& grid, int axis, int kmin, int kmax, double lo,
					 double hi)
{
	AxisCover ax;
	const double res = tree.getResolution(), nudge = grid.cellSize() * 1e-6;  // a bound on a voxel edge is not in the next
	const int n = kmax - kmin + 1;
	for (int l = 0; l < n; l++)
	{
		const double centre = tree.keyToCoord(static_cast<octomap::key_type>(kmin + l));
		const double from = std::max(centre - 0.5 * res, lo), to = std::min(centre + 0.5 * res, hi);
		ax.first.push_back(grid.keyAlong(axis, static_cast<float>(from + nudge)));
		ax.last.push_back(grid.keyAlong(axis, static_cast<float>(to - nudge)));
	}
	ax.keyLo = *std::min_element(ax.first.begin(), ax.first.end());
	const int keyHi = *std::max_element(ax.last.begin(), ax.last.end());
	ax.leaves.assign(static_cast<size_t>(std::max(0, keyHi - ax.keyLo + 1)), {INT_MAX, INT_MIN});
	for (int l = 0; l < n; l++)
		for (int k = ax.first[l]; k <= ax.last[l]; k++)
		{
			auto& cover = ax.leaves[static_cast<size_t>(k - ax.keyLo)];
			cover = {std::min(cover.first, l), std::max(cover.second, l)};
		}
	return ax;
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
		// The leaf of each voxel's centre (as an octomap::point3d: floats),
		// axis by axis: a row's y and z keys once per row.
		const auto leafKey = [&](int axis, int32_t key, octomap::key_type& out) {
			return tree_->coordToKeyChecked(static_cast<float>(grid.centerAlong(axis, key)), out);
		};
		VoxelKey row{0, -1, -1};
		bool rowInTree = false;
		octomap::OcTreeKey k;
		grid.forEachVoxelKey(b, e, [&](size_t, const VoxelKey& vk) {
			if (vk.y != row.y || vk.z != row.z)
			{
				row = vk;
				rowInTree = leafKey(1, vk.y, k[1]) && leafKey(2, vk.z, k[2]);
			}
			if (!rowInTree || !leafKey(0, vk.x, k[0])) return;
			const uint64_t packed = k[0] | (uint64_t{k[1]} << 16) | (uint64_t{k[2]} << 32);
			if (part.empty() || part.back() != packed) part.push_back(packed);  // runs along x share a leaf
		});
		// Rows next to each other share leaves too: each worker sorts out
		// its own repeats, the merge below only those between workers.
		std::sort(part.begin(), part.end());
		part.erase(std::unique(part.begin(), part.end()), part.end());
	});
	std::vector<uint64_t> leaves;
	for (auto& part : parts)
	{
		const auto middle = static_cast<std::ptrdiff_t>(leaves.size());
		leaves.insert(leaves.end(), part.begin(), part.end());
		std::inplace_merge(leaves.begin(), leaves.begin() + middle, leaves.end());
		part = {};
	}
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

std::vector<VoxelGrid::KeySpan> OctreeGatherer::rowsUnderOccupiedLeaves(const Eigen::Vector3d& lo,
																	   const Eigen::Vector3d& hi) const
{
	// The occupied leaves within [lo, hi], as index ranges on the leaves'
	// lattice (every leaf is at the tree's full depth: it is never pruned,
	// but a coarser node would cover its range of leaves).
	struct Node
	{
		std::array<int, 3> first, last;
	};
	std::vector<Node> nodes;
	std::array<int, 3> kmin{INT_MAX, INT_MAX, INT_MAX}, kmax{INT_MIN, INT_MIN, INT_MIN};
	const double res = tree_->getResolution();
	for (auto it = tree_->begin_leafs_bbx(octomap::point3d(lo.x(), lo.y(), lo.z()),
										 octomap::point3d(hi.x(), hi.y(), hi.z())),
			  end = tree_->end_leafs_bbx();
		 it != end; ++it)
	{
		if (!tree_->isNodeOccupied(*it)) continue;
		const double c[3] = {it.getX(), it.getY(), it.getZ()}, half = 0.5 * (it.getSize() - res);
		Node n;
		for (int a = 0; a < 3; a++)
		{
			n.first[a] = tree_->coordToKey(c[a] - half);
			n.last[a] = tree_->coordToKey(c[a] + half);
			kmin[a] = std::min(kmin[a], n.first[a]);
			kmax[a] = std::max(kmax[a], n.last[a]);
		}
		nodes.push_back(n);
	}
	if (nodes.empty()) return {};

	const std::array<AxisCover, 3> axis = {coverAlong(*tree_, grid_, 0, kmin[0], kmax[0], lo[0], hi[0]),
											coverAlong(*tree_, grid_, 1, kmin[1], kmax[1], lo[1], hi[1]),
											coverAlong(*tree_, grid_, 2, kmin[2], kmax[2], lo[2], hi[2])};

	// Occupancy as bit rows along x, one per leaf (y, z).
	const int nx = kmax[0] - kmin[0] + 1, ny = kmax[1] - kmin[1] + 1, nz = kmax[2] - kmin[2] + 1;
	const size_t words = static_cast<size_t>(nx + 63) / 64;
	std::vector<uint64_t> occupied(words * static_cast<size_t>(ny) * static_cast<size_t>(nz), 0);
	const auto row = [&](int ly, int lz) { return &occupied[(static_cast<size_t>(lz) * ny + ly) * words]; };
	for (const Node& n : nodes)
		for (int z = n.first[2]; z <= n.last[2]; z++)
			for (int y = n.first[1]; y <= n.last[1]; y++)
			{
				uint64_t* bits = row(y - kmin[1], z - kmin[2]);
				for (int x = n.first[0]; x <= n.last[0]; x++) bits[(x - kmin[0]) / 64] |= uint64_t{1} << ((x - kmin[0]) % 64);
			}

	// Each voxel row (y, z): the x ranges of the leaves over it, in key
	// order and joined, so the rows come out sorted and few. (A span per
	// leaf and row, sorted afterwards, was a third of a gather's time.)
	std::vector<VoxelGrid::KeySpan> spans;
	std::vector<uint64_t> over(words);
	for (size_t zk = 0; zk < axis[2].leaves.size(); zk++)
		for (size_t yk = 0; yk < axis[1].leaves.size(); yk++)
		{
			const auto [za, zb] = axis[2].leaves[zk];
			const auto [ya, yb] = axis[1].leaves[yk];
			std::fill(over.begin(), over.end(), 0);
			for (int lz = za; lz <= zb; lz++)
				for (int ly = ya; ly <= yb; ly++)
				{
					const uint64_t* bits = row(ly, lz);
					for (size_t w = 0; w < words; w++) over[w] |= bits[w];
				}
			const int y = axis[1].keyLo + static_cast<int>(yk), z = axis[2].keyLo + static_cast<int>(zk);
			VoxelGrid::KeySpan r;
			bool open = false;
			int x0 = 0, x1 = 0;
			for (int l = 0; l < nx; l++)
			{
				if (!(over[static_cast<size_t>(l) / 64] >> (l % 64) & 1)) continue;
				const AxisCover& ax = axis[0];
				if (open && ax.first[l] <= x1 + 1)
				{
					x1 = std::max(x1, ax.last[l]);
					continue;
				}
				if (open && grid_.rowSpan(x0, x1, y, z, r)) spans.push_back(r);
				open = true, x0 = ax.first[l], x1 = ax.last[l];
			}
			if (open && grid_.rowSpan(x0, x1, y, z, r)) spans.push_back(r);
		}
	return spans;
}

std::vector<uint32_t> OctreeGatherer::gather(const OrientedBox& box, double spacing, const float* xs,
											 const float* ys, const float* zs) const
{
	const Eigen::Vector3d half(0.5 * box.extent.x() * params_.enlarge, 0.5 * box.extent.y() * params_.enlarge,
							   0.5 * box.extent.z() + params_.slabSpacings * spacing);
	// Axis-aligned bounds of the enlarged box, for the octree query.
	const Eigen::Vector3d reach = box.axes.cwiseAbs() * half;
	const Eigen::Vector3d lo = box.center - reach, hi = box.center + reach;
	std::vector<uint32_t> out;
	const auto keepInside = [&](size_t v) {
		for (const uint32_t* p = grid_.begin(v); p != grid_.end(v); ++p)
		{
			const Eigen::Vector3d q = box.axes.transpose() * (Eigen::Vector3d(xs[*p], ys[*p], zs[*p]) - box.center);
			if (std::abs(q.x()) <= half.x() && std::abs(q.y()) <= half.y() && std::abs(q.z()) <= half.z())
				out.push_back(*p);
		}
	};
	if (tree_) grid_.forEachVoxelInSpans(rowsUnderOccupiedLeaves(lo, hi), keepInside);
	else
	{
		// A bound on a voxel's edge is not in the voxel beyond it.
		const double nudge = grid_.cellSize() * 1e-6;
		grid_.forEachVoxelInBlock(grid_.keyOf((lo.array() + nudge).matrix().cast<float>()),
								  grid_.keyOf((hi.array() - nudge).matrix().cast<float>()), keepInside);
	}
	radixSort(out);  // each voxel was visited once: no point twice
	return out;
}

}  // namespace tagmap
