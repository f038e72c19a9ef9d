#include "tagmap/point_spacing.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace tagmap
{
namespace
{
uint64_t cellKey(int64_t x, int64_t y, int64_t z)
{
	const uint64_t m = (1ULL << 21) - 1;
	return (static_cast<uint64_t>(x) & m) | ((static_cast<uint64_t>(y) & m) << 21) | ((static_cast<uint64_t>(z) & m) << 42);
}
}  // namespace

double estimatePointSpacing(const float* xs, const float* ys, const float* zs, size_t n, const PointSpacingParams& p)
{
	if (n < 2) return 0;
	Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max()), hi = -lo;
	for (size_t i = 0; i < n; i++)
	{
		const Eigen::Vector3d q(xs[i], ys[i], zs[i]);
		lo = lo.cwiseMin(q);
		hi = hi.cwiseMax(q);
	}
	const Eigen::Vector3d ext = (hi - lo).cwiseMax(1e-3);
	const size_t stride = std::max<size_t>(1, n / p.samples);
	std::vector<size_t> samples;
	for (size_t i = stride / 2; i < n; i += stride) samples.push_back(i);

	// Start below any plausible spacing and double the cell until at least
	// half of the samples have their nearest neighbour within one cell: a
	// neighbour closer than the cell is always in the 3x3x3 block, so the
	// median is exact once more than half are resolved.
	double cell = std::cbrt(ext.prod() / static_cast<double>(n)) / 16;
	cell = std::max(cell, ext.maxCoeff() * 1e-6);
	for (int pass = 0; pass < 40; pass++, cell *= 2)
	{
		auto key = [&](size_t i, int dx, int dy, int dz) {
			return cellKey(static_cast<int64_t>(std::floor((xs[i] - lo.x()) / cell)) + dx,
						   static_cast<int64_t>(std::floor((ys[i] - lo.y()) / cell)) + dy,
						   static_cast<int64_t>(std::floor((zs[i] - lo.z()) / cell)) + dz);
		};
		std::unordered_map<uint64_t, std::vector<uint32_t>> buckets;
		for (size_t s : samples)
			for (int dz = -1; dz <= 1; dz++)
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++) buckets[key(s, dx, dy, dz)];
		size_t collected = 0;
		bool tooCoarse = false;
		for (size_t i = 0; i < n && !tooCoarse; i++)
		{
			auto it = buckets.find(key(i, 0, 0, 0));
			if (it == buckets.end()) continue;
			it->second.push_back(static_cast<uint32_t>(i));
			tooCoarse = ++collected > 200 * samples.size() + 100000;
		}
		if (tooCoarse) return cell;  // cannot happen when growing from small; a safe bound anyway
		std::vector<double> nn;
		for (size_t s : samples)
		{
			double best = std::numeric_limits<double>::max();
			for (int dz = -1; dz <= 1; dz++)
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++)
						for (uint32_t j : buckets[key(s, dx, dy, dz)])
						{
							if (j == s) continue;
							const double d = std::hypot(xs[j] - xs[s], ys[j] - ys[s], zs[j] - zs[s]);
							if (d > 0) best = std::min(best, d);
						}
			nn.push_back(best);
		}
		std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
		if (nn[nn.size() / 2] <= cell) return nn[nn.size() / 2];
	}
	return cell;
}

}  // namespace tagmap
