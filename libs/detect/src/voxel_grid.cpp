#include "tagmap/voxel_grid.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "tagmap/parallel.h"

namespace tagmap
{
namespace
{
constexpr int32_t kMaxCells = 1 << 20;  // per axis

int bitsFor(uint64_t maxValue)
{
	int b = 1;
	while (b < 64 && (maxValue >> b) != 0) b++;
	return b;
}

// Stable LSD radix sort of `a` by bits [lowBit, highBit), in passes of at
// most 11 bits. Each pass: per-chunk histograms, prefix sums in (digit,
// chunk) order, per-chunk scatter; the result is the same for any `threads`.
void radixSort(FilledInParallel<uint64_t>& a, int lowBit, int highBit, unsigned threads)
{
	const size_t n = a.size();
	FilledInParallel<uint64_t> tmp(n);  // every element is written by the first pass's scatter
	const int passes = (highBit - lowBit + 10) / 11;
	const int width = passes ? (highBit - lowBit + passes - 1) / passes : 0;
	threads = n < 65536 ? 1u : std::max(1u, threads);
	for (int shift = lowBit; shift < highBit; shift += width)
	{
		const int bits = std::min(width, highBit - shift);
		const size_t buckets = size_t{1} << bits;
		const uint64_t mask = buckets - 1;
		std::vector<size_t> hist(threads * buckets, 0);
		parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
			size_t* h = hist.data() + c * buckets;
			for (size_t i = b; i < e; i++) h[(a[i] >> shift) & mask]++;
		});
		size_t pos = 0;
		for (size_t d = 0; d < buckets; d++)
			for (unsigned c = 0; c < threads; c++)
			{
				const size_t count = hist[c * buckets + d];
				hist[c * buckets + d] = pos;
				pos += count;
			}
		parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
			size_t* h = hist.data() + c * buckets;
			for (size_t i = b; i < e; i++) tmp[h[(a[i] >> shift) & mask]++] = a[i];
		});
		a.swap(tmp);
	}
}
}  // namespace

void pointBounds(const float* xs, const float* ys, const float* zs, size_t n, unsigned threads, Eigen::Vector3d& lo,
				 Eigen::Vector3d& hi)
{
	threads = std::max(1u, threads);
	std::vector<Eigen::Array3f> los(threads, Eigen::Array3f::Constant(std::numeric_limits<float>::max()));
	std::vector<Eigen::Array3f> his(threads, Eigen::Array3f::Constant(-std::numeric_limits<float>::max()));
	parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
		Eigen::Array3f l = los[c], h = his[c];
		for (size_t i = b; i < e; i++)
		{
			const Eigen::Array3f q(xs[i], ys[i], zs[i]);
			l = l.min(q);
			h = h.max(q);
		}
		los[c] = l;
		his[c] = h;
	});
	for (unsigned c = 1; c < threads; c++) los[0] = los[0].min(los[c]), his[0] = his[0].max(his[c]);
	lo = n ? Eigen::Vector3d(los[0].cast<double>().matrix()) : Eigen::Vector3d::Zero();
	hi = n ? Eigen::Vector3d(his[0].cast<double>().matrix()) : Eigen::Vector3d::Zero();
}

VoxelGrid::VoxelGrid(const float* xs, const float* ys, const float* zs, size_t n, double cellSize, unsigned threads)
	: cellSize_(cellSize)
{
	if (!(cellSize > 0)) throw std::invalid_argument("voxel size must be positive");
	if (n >= std::numeric_limits<uint32_t>::max()) throw std::invalid_argument("too many points (max 4e9)");
	threads = n < 65536 ? 1u : resolveThreads(threads);

	pointBounds(xs, ys, zs, n, threads, lo_, hi_);
	// Two cells of slack on either side: neighbour keys (x +- 1) stay inside
	// the box, so linear keys of neighbours never wrap into another row.
	origin_ = lo_ - Eigen::Vector3d::Constant(2 * cellSize);
	const Eigen::Vector3d cells = (hi_ - origin_) / cellSize;
	const float* coords[3] = {xs, ys, zs};
	for (int a = 0; a < 3; a++)
	{
		if (cells[a] <= kMaxCells - 4)
		{
			dims_[a] = static_cast<uint64_t>(std::floor(cells[a])) + 3;
			continue;
		}
		// Too wide: number the occupied cells densely, gaps of 3+ cells
		// shortened to 2 (still not adjacent). Only maps with far outliers
		// or kilometres of fine cells get here.
		Axis& ax = axis_[a];
		ax.packed = true;
		ax.real.resize(n);
		parallelForBlocks(n, threads, [&](size_t b, size_t e) {
			for (size_t i = b; i < e; i++) ax.real[i] = realCell(coords[a][i], a);
		}, 1 << 16);
		std::sort(ax.real.begin(), ax.real.end());
		ax.real.erase(std::unique(ax.real.begin(), ax.real.end()), ax.real.end());
		if (ax.real.size() > static_cast<size_t>(kMaxCells) * 512)
			throw std::invalid_argument("too many distinct voxel rows for a " + std::to_string(cellSize) + " m voxel");
		ax.key.resize(ax.real.size());
		for (size_t k = 0; k < ax.real.size(); k++)
			ax.key[k] = k == 0 ? 2 : ax.key[k - 1] + static_cast<int32_t>(std::min<int64_t>(ax.real[k] - ax.real[k - 1], 2));
		dims_[a] = static_cast<uint64_t>(ax.key.empty() ? 2 : ax.key.back()) + 3;
	}
	uint64_t cellCount;
	if (__builtin_mul_overflow(dims_[0], dims_[1], &cellCount) || __builtin_mul_overflow(cellCount, dims_[2], &cellCount) ||
		cellCount > (uint64_t{1} << 63))
		throw std::invalid_argument("the map's occupied voxels of " + std::to_string(cellSize) +
									" m cannot be numbered in 64 bits");

	const int keyBits = bitsFor(cellCount - 1);
	const int idxBits = bitsFor(n > 0 ? n - 1 : 0);
	auto keyOfPoint = [&](size_t i) { return linear(keyOf(Eigen::Vector3f(xs[i], ys[i], zs[i]))); };
	order_.resize(n);
	if (keyBits + idxBits <= 64)
	{
		// key << idxBits | index in one word: sorting by the key bits keeps
		// equal keys in index order (the sort is stable), as a sort of
		// (key, index) pairs would.
		FilledInParallel<uint64_t> a(n);
		parallelForBlocks(n, threads, [&](size_t b, size_t e) {
			for (size_t i = b; i < e; i++) a[i] = (keyOfPoint(i) << idxBits) | i;
		}, 1 << 16);
		radixSort(a, idxBits, idxBits + keyBits, threads);
		// The voxels start where the sorted key changes: counted per chunk,
		// then written at their places in parallel with the points' order
		// (a push_back per voxel on one thread, its growth and the final
		// shrink copied some 100 MB at the city's 20 M points).
		const uint64_t idxMask = idxBits == 64 ? ~uint64_t{0} : (uint64_t{1} << idxBits) - 1;
		const auto startsVoxel = [&](size_t i) { return i == 0 || (a[i] >> idxBits) != (a[i - 1] >> idxBits); };
		std::vector<size_t> firstVoxelOfChunk(threads + 1, 0);
		parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
			size_t starts = 0;  // counted locally: the chunks' totals share a cache line
			for (size_t i = b; i < e; i++) starts += startsVoxel(i);
			firstVoxelOfChunk[c + 1] = starts;
		});
		for (unsigned c = 0; c < threads; c++) firstVoxelOfChunk[c + 1] += firstVoxelOfChunk[c];
		keys_.resize(firstVoxelOfChunk[threads]);
		voxelStart_.resize(firstVoxelOfChunk[threads] + 1);
		voxelStart_.back() = static_cast<uint32_t>(n);
		parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
			size_t v = firstVoxelOfChunk[c];
			for (size_t i = b; i < e; i++)
			{
				order_[i] = static_cast<uint32_t>(a[i] & idxMask);
				if (!startsVoxel(i)) continue;
				voxelStart_[v] = static_cast<uint32_t>(i);
				keys_[v++] = a[i] >> idxBits;
			}
		});
	}
	else
	{
		std::vector<std::pair<uint64_t, uint32_t>> keyed(n);
		for (size_t i = 0; i < n; i++) keyed[i] = {keyOfPoint(i), static_cast<uint32_t>(i)};
		std::sort(keyed.begin(), keyed.end());
		for (size_t i = 0; i < n; i++)
		{
			if (i == 0 || keyed[i].first != keys_.back())
			{
				voxelStart_.push_back(static_cast<uint32_t>(i));
				keys_.push_back(keyed[i].first);
			}
			order_[i] = keyed[i].second;
		}
		voxelStart_.push_back(static_cast<uint32_t>(n));
		keys_.shrink_to_fit();
		voxelStart_.shrink_to_fit();
	}
}

int32_t VoxelGrid::Axis::packedKeyOf(int64_t r) const
{
	const size_t k = static_cast<size_t>(std::lower_bound(real.begin(), real.end(), r) - real.begin());
	if (k < real.size() && real[k] == r) return key[k];
	// Between occupied cells: the empty key after the lower one, which is
	// adjacent to it only if the real cells are adjacent too. Below all: 1.
	return k == 0 ? 1 : key[k - 1] + 1;
}

int64_t VoxelGrid::Axis::realOf(int32_t k) const
{
	if (!packed) return k;
	const size_t j = static_cast<size_t>(std::upper_bound(key.begin(), key.end(), k) - key.begin());
	return j == 0 ? real.front() - (key.front() - k) : real[j - 1] + (k - key[j - 1]);
}

VoxelKey VoxelGrid::keyOfVoxel(size_t voxel) const
{
	const uint64_t k = keys_[voxel], row = k / dims_[0];
	return {static_cast<int32_t>(k - row * dims_[0]), static_cast<int32_t>(row % dims_[1]),
			static_cast<int32_t>(row / dims_[1])};
}

Eigen::Vector3d VoxelGrid::voxelCenter(const VoxelKey& k) const
{
	return {centerAlong(0, k.x), centerAlong(1, k.y), centerAlong(2, k.z)};
}

int64_t VoxelGrid::find(const VoxelKey& k) const
{
	if (k.x < 0 || k.y < 0 || k.z < 0 || static_cast<uint64_t>(k.x) >= dims_[0] ||
		static_cast<uint64_t>(k.y) >= dims_[1] || static_cast<uint64_t>(k.z) >= dims_[2])
		return -1;
	const uint64_t key = linear(k);
	const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
	return it != keys_.end() && *it == key ? it - keys_.begin() : -1;
}

VoxelGrid::NeighbourSweep::NeighbourSweep(const VoxelGrid& g, size_t firstVoxel) : g_(g)
{
	const uint64_t k = firstVoxel < g.keys_.size() ? g.keys_[firstVoxel] : 0;
	for (int j = 0; j < 9; j++)
	{
		const int64_t dy = j % 3 - 1, dz = j / 3 - 1;
		const uint64_t lo = k + static_cast<uint64_t>(dy * static_cast<int64_t>(g.dims_[0]) +
													  dz * static_cast<int64_t>(g.dims_[0] * g.dims_[1])) - 1;
		cursor_[j] = static_cast<size_t>(std::lower_bound(g.keys_.begin(), g.keys_.end(), lo) - g.keys_.begin());
	}
}

int VoxelGrid::NeighbourSweep::rows(size_t v, Row (&out)[9])
{
	const auto& keys = g_.keys_;
	const size_t count = keys.size();
	const int64_t d0 = static_cast<int64_t>(g_.dims_[0]), d01 = static_cast<int64_t>(g_.dims_[0] * g_.dims_[1]);
	const uint64_t k = keys[v];
	int found = 0;
	for (int j = 0; j < 9; j++)
	{
		const uint64_t lo = k + static_cast<uint64_t>((j % 3 - 1) * d0 + (j / 3 - 1) * d01) - 1, hi = lo + 2;
		size_t c = cursor_[j];
		while (c < count && keys[c] < lo) c++;
		cursor_[j] = c;
		size_t end = c;
		while (end < count && keys[end] <= hi) end++;
		if (end > c) out[found++] = {static_cast<uint32_t>(c), static_cast<uint32_t>(end)};
	}
	return found;
}

int VoxelGrid::NeighbourSweep::neighbours(size_t v, uint32_t (&out)[27])
{
	Row block[9];
	const int rowCount = rows(v, block);
	int found = 0;
	for (int r = 0; r < rowCount; r++)
		for (uint32_t c = block[r].first; c < block[r].end; c++) out[found++] = c;
	return found;
}

}  // namespace tagmap
