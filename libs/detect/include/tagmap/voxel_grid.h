// The neighbour index every stage shares: points bucketed into cubic voxels
// (a sorted index plus a hash from voxel key to its range), so "points near
// p" is a handful of contiguous ranges. Built once per pipeline run.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace tagmap
{
struct VoxelKey
{
	int32_t x = 0, y = 0, z = 0;
	bool operator==(const VoxelKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

class VoxelGrid
{
   public:
	/** Buckets points (xs/ys/zs of length n) into voxels of edge `cellSize`.
	 *  Throws std::invalid_argument if the extent does not fit 2^20 cells. */
	VoxelGrid(const float* xs, const float* ys, const float* zs, size_t n, double cellSize);

	double cellSize() const { return cellSize_; }
	size_t voxelCount() const { return voxelStart_.size() - 1; }

	VoxelKey keyOf(const Eigen::Vector3f& p) const;
	VoxelKey keyOfVoxel(size_t voxel) const { return voxelKeys_[voxel]; }
	Eigen::Vector3d voxelCenter(const VoxelKey& k) const;

	/** Voxel index for a key, or -1 when empty. */
	int64_t find(const VoxelKey& k) const;

	/** Point indices of a voxel, as a contiguous range of pointOrder(). */
	const uint32_t* begin(size_t voxel) const { return order_.data() + voxelStart_[voxel]; }
	const uint32_t* end(size_t voxel) const { return order_.data() + voxelStart_[voxel + 1]; }
	size_t voxelSize(size_t voxel) const { return voxelStart_[voxel + 1] - voxelStart_[voxel]; }

	/** Voxel of each point (index into voxels). */
	uint32_t voxelOfPoint(size_t pointIndex) const { return voxelOfPoint_[pointIndex]; }

	/** Calls f(voxelIndex) for every non-empty voxel in the (2r+1)^3 block around k. */
	template <typename F>
	void forEachNeighbourVoxel(const VoxelKey& k, int r, F&& f) const
	{
		for (int dz = -r; dz <= r; dz++)
			for (int dy = -r; dy <= r; dy++)
				for (int dx = -r; dx <= r; dx++)
				{
					const int64_t v = find({k.x + dx, k.y + dy, k.z + dz});
					if (v >= 0) f(static_cast<size_t>(v));
				}
	}

   private:
	static uint64_t pack(const VoxelKey& k);
	double cellSize_;
	Eigen::Vector3d origin_;
	std::vector<uint32_t> order_;  // point indices sorted by voxel
	std::vector<uint32_t> voxelStart_;  // voxel v owns order_[voxelStart_[v], voxelStart_[v+1])
	std::vector<VoxelKey> voxelKeys_;
	std::vector<uint32_t> voxelOfPoint_;
	// Open-addressing hash: packed key -> voxel index.
	std::vector<uint64_t> hashKeys_;
	std::vector<uint32_t> hashValues_;
	uint64_t hashMask_ = 0;
};

}  // namespace tagmap
