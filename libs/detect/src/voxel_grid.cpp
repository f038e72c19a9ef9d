#include "tagmap/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tagmap
{
namespace
{
constexpr int kBits = 21;  // per axis: 2M cells, 63 bits in all
constexpr int32_t kMaxCells = 1 << 20;  // leaves room for neighbour offsets
constexpr uint64_t kEmpty = std::numeric_limits<uint64_t>::max();

uint64_t mix(uint64_t h)
{
	h ^= h >> 33;
	h *= 0xff51afd7ed558ccdULL;
	h ^= h >> 33;
	return h;
}
}  // namespace

uint64_t VoxelGrid::pack(const VoxelKey& k)
{
	const uint64_t m = (1ULL << kBits) - 1;
	return (static_cast<uint64_t>(k.x) & m) | ((static_cast<uint64_t>(k.y) & m) << kBits) |
		   ((static_cast<uint64_t>(k.z) & m) << (2 * kBits));
}

VoxelGrid::VoxelGrid(const float* xs, const float* ys, const float* zs, size_t n, double cellSize)
	: cellSize_(cellSize)
{
	if (!(cellSize > 0)) throw std::invalid_argument("voxel size must be positive");
	if (n >= std::numeric_limits<uint32_t>::max()) throw std::invalid_argument("too many points (max 4e9)");
	Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
	Eigen::Vector3d hi = -lo;
	for (size_t i = 0; i < n; i++)
	{
		lo = lo.cwiseMin(Eigen::Vector3d(xs[i], ys[i], zs[i]));
		hi = hi.cwiseMax(Eigen::Vector3d(xs[i], ys[i], zs[i]));
	}
	if (n == 0) lo = hi = Eigen::Vector3d::Zero();
	// One cell of slack so neighbour offsets never go negative.
	origin_ = lo - Eigen::Vector3d::Constant(2 * cellSize);
	const Eigen::Vector3d cells = (hi - origin_) / cellSize;
	if (cells.maxCoeff() > kMaxCells - 4)
		throw std::invalid_argument("map extent " + std::to_string((hi - lo).maxCoeff()) + " m is too large for a " +
									std::to_string(cellSize) + " m voxel (more than 2^20 voxels across)");

	// Sort points by packed key. Keys are 63-bit: a 3-pass LSD radix sort on
	// 21-bit digits would be the next speed-up; std::sort keeps it simple.
	std::vector<std::pair<uint64_t, uint32_t>> keyed(n);
	for (size_t i = 0; i < n; i++)
		keyed[i] = {pack(keyOf(Eigen::Vector3f(xs[i], ys[i], zs[i]))), static_cast<uint32_t>(i)};
	std::sort(keyed.begin(), keyed.end());

	order_.resize(n);
	voxelOfPoint_.resize(n);
	voxelStart_.clear();
	for (size_t i = 0; i < n; i++)
	{
		if (i == 0 || keyed[i].first != keyed[i - 1].first)
		{
			voxelStart_.push_back(static_cast<uint32_t>(i));
			const uint32_t j = keyed[i].second;
			voxelKeys_.push_back(keyOf(Eigen::Vector3f(xs[j], ys[j], zs[j])));
		}
		order_[i] = keyed[i].second;
		voxelOfPoint_[keyed[i].second] = static_cast<uint32_t>(voxelStart_.size() - 1);
	}
	voxelStart_.push_back(static_cast<uint32_t>(n));

	size_t cap = 16;
	while (cap < 2 * voxelKeys_.size()) cap <<= 1;
	hashMask_ = cap - 1;
	hashKeys_.assign(cap, kEmpty);
	hashValues_.assign(cap, 0);
	for (size_t v = 0; v < voxelKeys_.size(); v++)
	{
		const uint64_t key = pack(voxelKeys_[v]);
		uint64_t slot = mix(key) & hashMask_;
		while (hashKeys_[slot] != kEmpty) slot = (slot + 1) & hashMask_;
		hashKeys_[slot] = key;
		hashValues_[slot] = static_cast<uint32_t>(v);
	}
}

VoxelKey VoxelGrid::keyOf(const Eigen::Vector3f& p) const
{
	return {static_cast<int32_t>(std::floor((p.x() - origin_.x()) / cellSize_)),
			static_cast<int32_t>(std::floor((p.y() - origin_.y()) / cellSize_)),
			static_cast<int32_t>(std::floor((p.z() - origin_.z()) / cellSize_))};
}

Eigen::Vector3d VoxelGrid::voxelCenter(const VoxelKey& k) const
{
	return origin_ + cellSize_ * Eigen::Vector3d(k.x + 0.5, k.y + 0.5, k.z + 0.5);
}

int64_t VoxelGrid::find(const VoxelKey& k) const
{
	if (k.x < 0 || k.y < 0 || k.z < 0 || k.x >= kMaxCells || k.y >= kMaxCells || k.z >= kMaxCells) return -1;
	const uint64_t key = pack(k);
	uint64_t slot = mix(key) & hashMask_;
	while (true)
	{
		const uint64_t s = hashKeys_[slot];
		if (s == key) return hashValues_[slot];
		if (s == kEmpty) return -1;
		slot = (slot + 1) & hashMask_;
	}
}

}  // namespace tagmap
