#include "tagmap/quantile.h"
#include "tagmap/point_spacing.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "tagmap/parallel.h"
#include "tagmap/voxel_grid.h"

namespace tagmap
{
namespace
{
constexpr uint64_t kEmpty = std::numeric_limits<uint64_t>::max();

uint64_t cellKey(int64_t x, int64_t y, int64_t z)
{
	const uint64_t m = (1ULL << 21) - 1;
	return (static_cast<uint64_t>(x) & m) | ((static_cast<uint64_t>(y) & m) << 21) | ((static_cast<uint64_t>(z) & m) << 42);
}

// Open-addressing map from cell key to a dense bucket id; small (27 cells
// per sample), so it stays in cache while every point of the map probes it.
class CellTable
{
   public:
	explicit CellTable(size_t expected)
	{
		size_t cap = 64;
		int bits = 6;
		while (cap < 2 * expected) cap <<= 1, bits++;
		keys_.assign(cap, kEmpty);
		ids_.assign(cap, 0);
		mask_ = cap - 1;
		shift_ = 64 - bits;
	}
	/** The bucket id of `k`, a new one (the next) if `k` was not in. */
	uint32_t insert(uint64_t k)
	{
		uint64_t s = slot(k);
		while (keys_[s] != kEmpty && keys_[s] != k) s = (s + 1) & mask_;
		if (keys_[s] == k) return ids_[s];
		keys_[s] = k;
		return ids_[s] = count_++;
	}
	int64_t find(uint64_t k) const
	{
		for (uint64_t s = slot(k);; s = (s + 1) & mask_)
		{
			if (keys_[s] == k) return ids_[s];
			if (keys_[s] == kEmpty) return -1;
		}
	}
	uint32_t size() const { return count_; }

   private:
	// Fibonacci hashing: the product's top bits, which every bit of the
	// key (x, y and z packed in 21 bits each) reaches.
	uint64_t slot(uint64_t k) const { return (k * 0x9E3779B97F4A7C15ULL) >> shift_; }
	std::vector<uint64_t> keys_;
	std::vector<uint32_t> ids_;
	uint64_t mask_ = 0;
	int shift_ = 58;
	uint32_t count_ = 0;
};

// The bounding box's size, each axis cut to 10x the samples' 1st-99th
// percentile range beyond those percentiles: a few stray returns 2000 km off
// would otherwise set the starting cell (and the floor below which no cell
// is tried, 1e-6 of the extent) to metres. Real maps lie well inside the cut.
Eigen::Vector3d robustExtent(const float* xs, const float* ys, const float* zs, const std::vector<size_t>& samples,
							 const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
	Eigen::Vector3d ext = hi - lo;
	if (samples.size() < 100) return ext;
	const float* coords[3] = {xs, ys, zs};
	std::vector<float> v(samples.size());
	for (int a = 0; a < 3; a++)
	{
		for (size_t k = 0; k < samples.size(); k++) v[k] = coords[a][samples[k]];
		const double q1 = quantileInPlace(v, 0.01), q99 = quantileInPlace(v, 0.99), range = q99 - q1;
		ext[a] = std::min(hi[a], q99 + 10 * range) - std::max(lo[a], q1 - 10 * range);
	}
	return ext;
}

enum class Pass
{
	Resolved,  // more than half the samples have their nearest neighbour within one cell
	TooFine,
	TooCoarse  // too many points near the samples: the cell is far too large
};

// One pass over the map with cells of edge `cell`: every point in the
// samples' 3x3x3 cell blocks is bucketed, then each sample's nearest
// neighbour is searched in its block. A neighbour closer than the cell is
// always in the block, so the median is exact once more than half resolve.
Pass medianNearest(const float* xs, const float* ys, const float* zs, size_t n, const std::vector<size_t>& samples,
				   const Eigen::Vector3d& lo, double cell, unsigned threads, double& median)
{
	// A point's cell, once per point: its 3x3x3 block's keys are offsets of it.
	const auto cellOf = [&](size_t i) {
		return std::array<int64_t, 3>{static_cast<int64_t>(std::floor((xs[i] - lo.x()) / cell)),
									  static_cast<int64_t>(std::floor((ys[i] - lo.y()) / cell)),
									  static_cast<int64_t>(std::floor((zs[i] - lo.z()) / cell))};
	};
	const auto key = [](const std::array<int64_t, 3>& c, int dx, int dy, int dz) {
		return cellKey(c[0] + dx, c[1] + dy, c[2] + dz);
	};
	// The cells bucketed: the samples' blocks (27 cells each), so that a
	// large map's points far from every sample are skipped; or, when there
	// are fewer points than block cells (a scan), every point's own cell.
	// The same points fall in a sample's block either way.
	const bool everyPoint = n <= 27 * samples.size();
	CellTable cells(everyPoint ? n : 27 * samples.size());
	std::vector<uint32_t> ownBucket;  // every point's, when every point is bucketed
	if (everyPoint)
	{
		ownBucket.resize(n);
		for (size_t i = 0; i < n; i++) ownBucket[i] = cells.insert(key(cellOf(i), 0, 0, 0));
	}
	else
		for (size_t s : samples)
		{
			const std::array<int64_t, 3> c = cellOf(s);
			for (int dz = -1; dz <= 1; dz++)
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++) cells.insert(key(c, dx, dy, dz));
		}

	// (bucket, point) pairs per chunk of the map, in point order.
	const size_t limit = 200 * samples.size() + 100000;
	std::vector<std::vector<std::pair<uint32_t, uint32_t>>> parts(threads);
	std::atomic<size_t> collected{0};
	std::atomic<bool> tooCoarse{false};
	parallelForChunks(n, threads, [&](unsigned c, size_t b, size_t e) {
		auto& part = parts[c];
		for (size_t i = b; i < e; i++)
		{
			const int64_t id = everyPoint ? ownBucket[i] : cells.find(key(cellOf(i), 0, 0, 0));
			if (id < 0) continue;
			part.emplace_back(static_cast<uint32_t>(id), static_cast<uint32_t>(i));
			if ((part.size() & 1023) == 0 && collected.fetch_add(1024) + 1024 > limit)
			{
				tooCoarse = true;
				return;
			}
		}
	});
	size_t total = 0;
	for (const auto& part : parts) total += part.size();
	if (tooCoarse || total > limit) return Pass::TooCoarse;

	// Buckets as contiguous lists, points ascending within each.
	std::vector<uint32_t> start(cells.size() + 1, 0), members(total);
	for (const auto& part : parts)
		for (const auto& pr : part) start[pr.first + 1]++;
	for (size_t b = 0; b < cells.size(); b++) start[b + 1] += start[b];
	std::vector<uint32_t> fill(start.begin(), start.end() - 1);
	for (const auto& part : parts)
		for (const auto& pr : part) members[fill[pr.first]++] = pr.second;
	parts = {};

	std::vector<double> nn;
	nn.reserve(samples.size());
	for (size_t s : samples)
	{
		// The nearest by squared distance; std::hypot (whose overflow-safe
		// scaling cost more than the rest of the search) only for it, so the
		// spacing is the float distance it always was.
		double best = std::numeric_limits<double>::max();
		size_t nearest = s;
		const std::array<int64_t, 3> c = cellOf(s);
		for (int dz = -1; dz <= 1; dz++)
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++)
				{
					const int64_t id = cells.find(key(c, dx, dy, dz));
					if (id < 0) continue;  // an empty cell (only bucketed cells are kept)
					for (uint32_t k = start[id]; k < start[id + 1]; k++)
					{
						const uint32_t j = members[k];
						const double ex = xs[j] - xs[s], ey = ys[j] - ys[s], ez = zs[j] - zs[s];
						const double d2 = ex * ex + ey * ey + ez * ez;
						if (d2 > 0 && d2 < best) best = d2, nearest = j;
					}
				}
		nn.push_back(nearest == s ? std::numeric_limits<double>::max()
								  : std::hypot(xs[nearest] - xs[s], ys[nearest] - ys[s], zs[nearest] - zs[s]));
	}
	median = medianInPlace(nn);
	return median <= cell ? Pass::Resolved : Pass::TooFine;
}
}  // namespace

double estimatePointSpacing(const float* xs, const float* ys, const float* zs, size_t n, const PointSpacingParams& p,
							unsigned threads)
{
	if (n < 2) return 0;
	threads = n < 65536 ? 1u : resolveThreads(threads);
	Eigen::Vector3d lo, hi;
	pointBounds(xs, ys, zs, n, threads, lo, hi);
	const size_t stride = std::max<size_t>(1, n / p.samples);
	std::vector<size_t> samples;
	for (size_t i = stride / 2; i < n; i += stride) samples.push_back(i);
	const Eigen::Vector3d ext = robustExtent(xs, ys, zs, samples, lo, hi).cwiseMax(1e-3);

	// Any cell that resolves gives the same (exact) median, so the cell only
	// decides how many passes it takes. Start from the spacing of a 1/64
	// subsample: up to 8x the map's on surfaces (5.8x measured on the large
	// hall), 4x in volumes, so a quarter of it resolves in one pass. Without
	// a subsample to ask, a quarter of the spacing points filling the box's
	// volume would have: LiDAR points lie on surfaces, far sparser in 3D
	// than that, so this is still too fine and doubles up (a 24 k-point scan:
	// 2 passes, not 3-4), and each pass costs about what a resolving one does.
	const double floorCell = ext.maxCoeff() * 1e-6;
	double cell = std::cbrt(ext.prod() / static_cast<double>(n)) / 4;
	constexpr size_t kSub = 64;
	if (n >= kSub * 4096)
	{
		std::vector<float> sx, sy, sz;
		for (size_t i = 0; i < n; i += kSub)
		{
			sx.push_back(xs[i]);
			sy.push_back(ys[i]);
			sz.push_back(zs[i]);
		}
		const double sub = estimatePointSpacing(sx.data(), sy.data(), sz.data(), sx.size(), p, threads);
		if (sub > 0) cell = sub / 4;
	}
	cell = std::max(cell, floorCell);
	double median = 0, tooFine = 0, tooCoarse = 0;
	for (int pass = 0; pass < 40; pass++)
	{
		const Pass r = medianNearest(xs, ys, zs, n, samples, lo, cell, threads, median);
		if (r == Pass::Resolved) return median;
		if (r == Pass::TooFine) tooFine = cell;
		else tooCoarse = cell;
		if (tooCoarse > 0 && tooFine > 0 && tooCoarse <= 2 * tooFine) break;  // no cell resolves
		cell = tooCoarse > 0 ? (tooFine > 0 ? std::sqrt(tooFine * tooCoarse) : cell / 2) : cell * 2;
		if (cell < floorCell) break;
	}
	return tooCoarse > 0 ? tooCoarse : cell;
}

}  // namespace tagmap
