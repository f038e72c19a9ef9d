// The neighbour index every stage shares: points bucketed into cubic voxels.
// Voxels are numbered in ascending key order (z, then y, then x), each owns
// a contiguous range of a sorted point index, so "points near p" is a
// handful of contiguous ranges. Built once per pipeline run with a parallel
// LSD radix sort; no hash: a voxel's 26 neighbours come from a forward sweep
// over the sorted keys (NeighbourSweep), a single key from a binary search.
// No extent limit: an axis wider than 2^20 cells (a stray return 2000 km
// off) is packed, its empty stretches of 3 or more cells shortened to 2, so
// keys stay small, adjacency (+-1) and order are unchanged, and points far
// from everything simply have no neighbours. Axes that fit are not packed,
// so ordinary maps index exactly as before.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "tagmap/parallel.h"

namespace tagmap
{
struct VoxelKey
{
	int32_t x = 0, y = 0, z = 0;
	bool operator==(const VoxelKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

/** Axis-aligned bounds of n points (both zero when n == 0), with `threads`
 *  threads (exact: min and max do not depend on the split). */
void pointBounds(const float* xs, const float* ys, const float* zs, size_t n, unsigned threads, Eigen::Vector3d& lo,
				 Eigen::Vector3d& hi);

class VoxelGrid
{
   public:
	/** Buckets points (xs/ys/zs of length n) into voxels of edge `cellSize`,
	 *  with `threads` threads (0: all cores; the result does not depend on it).
	 *  Throws std::invalid_argument only if the occupied cells cannot be
	 *  numbered in 64 bits even packed. */
	VoxelGrid(const float* xs, const float* ys, const float* zs, size_t n, double cellSize, unsigned threads = 0);

	double cellSize() const { return cellSize_; }
	/** The bucketed points' axis-aligned bounds: no voxel lies beyond them. */
	const Eigen::Vector3d& lowerBound() const { return lo_; }
	const Eigen::Vector3d& upperBound() const { return hi_; }
	size_t voxelCount() const { return keys_.size(); }
	size_t pointCount() const { return order_.size(); }

	VoxelKey keyOf(const Eigen::Vector3f& p) const { return {keyAlong(0, p.x()), keyAlong(1, p.y()), keyAlong(2, p.z())}; }
	/** One axis of keyOf(): keys are separable, axis by axis. */
	int32_t keyAlong(int axis, float coordinate) const { return axis_[axis].keyOf(realCell(coordinate, axis)); }
	VoxelKey keyOfVoxel(size_t voxel) const;
	Eigen::Vector3d voxelCenter(const VoxelKey& k) const;
	/** One axis of voxelCenter(). */
	double centerAlong(int axis, int32_t key) const
	{
		return origin_[axis] + cellSize_ * (static_cast<double>(axis_[axis].realOf(key)) + 0.5);
	}

	/** Calls f(v, keyOfVoxel(v)) for the voxels [b, e) in order. Voxels of
	 *  one row follow each other: their keys differ in x only, found without
	 *  the divisions keyOfVoxel() takes for each voxel. */
	template <typename F>
	void forEachVoxelKey(size_t b, size_t e, F&& f) const
	{
		uint64_t rowStart = 1, rowEnd = 0;  // no row yet
		int32_t y = 0, z = 0;
		for (size_t v = b; v < e; v++)
		{
			const uint64_t k = keys_[v];
			if (k < rowStart || k >= rowEnd)
			{
				const VoxelKey first = keyOfVoxel(v);
				y = first.y, z = first.z;
				rowStart = k - static_cast<uint64_t>(first.x);
				rowEnd = rowStart + dims_[0];
			}
			f(v, VoxelKey{static_cast<int32_t>(k - rowStart), y, z});
		}
	}

	/** Voxel index for a key, or -1 when empty (binary search). */
	int64_t find(const VoxelKey& k) const;

	/** Point indices of a voxel, as a contiguous range; ascending within a voxel. */
	const uint32_t* begin(size_t voxel) const { return order_.data() + voxelStart_[voxel]; }
	const uint32_t* end(size_t voxel) const { return order_.data() + voxelStart_[voxel + 1]; }
	size_t voxelSize(size_t voxel) const { return voxelStart_[voxel + 1] - voxelStart_[voxel]; }
	/** Position of a voxel's first point in the sorted order (begin(v) - begin(0)). */
	size_t voxelOffset(size_t voxel) const { return voxelStart_[voxel]; }

	/** Voxels with linear keys first..last (inclusive): a stretch of a row,
	 *  or rows joined end to end (keys run along x, then y, then z). */
	struct KeySpan
	{
		uint64_t first = 0, last = 0;
	};

	/** The span of row (y, z) with x in [x0, x1], clipped to the grid;
	 *  false when nothing of it is in the grid. */
	bool rowSpan(int x0, int x1, int y, int z, KeySpan& out) const
	{
		if (y < 0 || z < 0 || static_cast<uint64_t>(y) >= dims_[1] || static_cast<uint64_t>(z) >= dims_[2]) return false;
		x0 = std::max(x0, 0);
		x1 = static_cast<int>(std::min<int64_t>(x1, static_cast<int64_t>(dims_[0]) - 1));
		if (x1 < x0) return false;
		out = {linear({x0, y, z}), linear({x1, y, z})};
		return true;
	}

	/** Calls f(voxelIndex) once for every non-empty voxel in any of `spans`
	 *  (in any order, overlapping or not), in ascending index. The spans are
	 *  sorted and those that touch joined; then one cursor moves forward
	 *  through the voxels: the first span's first voxel is a binary search,
	 *  each next one is found from where the span before ended by steps
	 *  doubling from there: a few probes near the cursor instead of a
	 *  binary search over every voxel of the map (most of a gather's time). */
	template <typename F>
	void forEachVoxelInSpans(std::vector<KeySpan> spans, F&& f) const
	{
		std::sort(spans.begin(), spans.end(), [](const KeySpan& a, const KeySpan& b) { return a.first < b.first; });
		size_t joined = 0;
		for (const KeySpan& s : spans)
			if (joined > 0 && s.first <= spans[joined - 1].last + 1)
				spans[joined - 1].last = std::max(spans[joined - 1].last, s.last);
			else
				spans[joined++] = s;
		spans.resize(joined);
		auto cursor = keys_.begin();
		for (size_t s = 0; s < spans.size(); s++)
		{
			cursor = s == 0 ? std::lower_bound(cursor, keys_.end(), spans[s].first) : firstNotBelow(cursor, spans[s].first);
			for (; cursor != keys_.end() && *cursor <= spans[s].last; ++cursor) f(static_cast<size_t>(cursor - keys_.begin()));
		}
	}

	/** Calls f(voxelIndex) for every non-empty voxel with a key in the block
	 *  [lo, hi] (each axis inclusive), in ascending index. */
	template <typename F>
	void forEachVoxelInBlock(const VoxelKey& lo, const VoxelKey& hi, F&& f) const
	{
		std::vector<KeySpan> spans;
		KeySpan r;
		for (int z = lo.z; z <= hi.z; z++)
			for (int y = lo.y; y <= hi.y; y++)
				if (rowSpan(lo.x, hi.x, y, z, r)) spans.push_back(r);
		forEachVoxelInSpans(std::move(spans), f);
	}

	/** Calls f(voxelIndex) for every non-empty voxel in the (2r+1)^3 block
	 *  around k, in ascending voxel index. For sweeping all voxels,
	 *  NeighbourSweep is much faster. */
	template <typename F>
	void forEachNeighbourVoxel(const VoxelKey& k, int r, F&& f) const
	{
		forEachVoxelInBlock({k.x - r, k.y - r, k.z - r}, {k.x + r, k.y + r, k.z + r}, f);
	}

	/** The 3x3x3 neighbourhoods of voxels visited in ascending order: nine
	 *  cursors (one per row y-1..y+1, z-1..z+1) only move forward, so a
	 *  sweep over V voxels costs O(V) sequential reads. */
	class NeighbourSweep
	{
	   public:
		NeighbourSweep(const VoxelGrid& g, size_t firstVoxel);
		/** Fills `out` with the non-empty voxels of v's 3x3x3 block (v
		 *  included) in ascending index; returns their number (<= 27). v must
		 *  not be less than the previous call's. */
		int neighbours(size_t v, uint32_t (&out)[27]);

		/** Voxels [first, end) of one row of a block: consecutive indices. */
		struct Row
		{
			uint32_t first, end;
		};
		/** The same block as neighbours(), as its non-empty rows (x-1..x+1
		 *  at one y and z) in ascending order; returns their number (<= 9).
		 *  The rows' points are contiguous in the grid's order. */
		int rows(size_t v, Row (&out)[9]);

	   private:
		const VoxelGrid& g_;
		size_t cursor_[9];
	};

   private:
	/** An axis's cell numbers: real cells (floor((p - origin) / cell))
	 *  as they are, or, when packed, the sorted occupied real cells and the
	 *  key each got. */
	struct Axis
	{
		bool packed = false;
		std::vector<int64_t> real;
		std::vector<int32_t> key;
		/** The key of real cell r: r itself on an axis not packed (inline:
		 *  every point of a map asks, some more than once). */
		int32_t keyOf(int64_t r) const
		{
			return packed ? packedKeyOf(r) : static_cast<int32_t>(std::clamp<int64_t>(r, INT32_MIN, INT32_MAX));
		}
		int32_t packedKeyOf(int64_t r) const;
		int64_t realOf(int32_t k) const;
	};
	int64_t realCell(double p, int a) const { return static_cast<int64_t>(std::floor((p - origin_[a]) / cellSize_)); }

	/** The first key at or after `from` not below `target`, by steps
	 *  doubling from `from`, then a binary search in the last step. */
	FilledInParallel<uint64_t>::const_iterator firstNotBelow(FilledInParallel<uint64_t>::const_iterator from, uint64_t target) const
	{
		if (from == keys_.end() || *from >= target) return from;
		auto below = from;  // *below < target
		for (std::ptrdiff_t step = 1;; step *= 2)
		{
			if (keys_.end() - below <= step) return std::lower_bound(below + 1, keys_.end(), target);
			if (below[step] >= target) return std::lower_bound(below + 1, below + step, target);
			below += step;
		}
	}

	uint64_t linear(const VoxelKey& k) const
	{
		return static_cast<uint64_t>(k.x) + dims_[0] * (static_cast<uint64_t>(k.y) + dims_[1] * static_cast<uint64_t>(k.z));
	}
	double cellSize_;
	Eigen::Vector3d origin_, lo_ = Eigen::Vector3d::Zero(), hi_ = Eigen::Vector3d::Zero();
	Axis axis_[3];
	uint64_t dims_[3] = {1, 1, 1};  // cells (keys) per axis, with a slack of 2 on either side
	FilledInParallel<uint32_t> order_;  // point indices sorted by voxel
	FilledInParallel<uint32_t> voxelStart_;  // voxel v owns order_[voxelStart_[v], voxelStart_[v+1])
	FilledInParallel<uint64_t> keys_;  // linear key of each voxel, ascending
};

}  // namespace tagmap
