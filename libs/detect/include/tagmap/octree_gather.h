// Stage 4 (paper, Sec. II-E, first half): collect the raw map points inside
// a candidate's enlarged box. An OctoMap occupancy octree over the map lets
// the search descend only into occupied space, so a box that spans empty
// air or a large room costs what its occupied surface costs.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "tagmap/clustering.h"
#include "tagmap/voxel_grid.h"

namespace octomap
{
class OcTree;
}

namespace tagmap
{
struct GatherParams
{
	double enlarge = 1.6;  // box length and width are multiplied by this (paper's t_b)
	/** Half thickness of the gathered slab, in point spacings, on top of the
	 *  box's own half height: keeps the tag's plane, drops what is behind. */
	double slabSpacings = 4.0;
	int octreeCellsPerLeaf = 4;  // octree leaf edge = this many neighbour-grid voxels (DerivedLengths::octreeLeaf)
};

class OctreeGatherer
{
   public:
	/** An occupancy tree with leaves of edge `leaf` (metres, at least the
	 *  grid's cell) over the grid's occupied voxels. `threads`: for the
	 *  build (0: all cores; the tree does not depend on it). */
	OctreeGatherer(const VoxelGrid& grid, double leaf, const GatherParams& p, unsigned threads = 0);
	~OctreeGatherer();

	/** Map indices of the points inside `box` enlarged by the parameters. */
	std::vector<uint32_t> gather(const OrientedBox& box, double spacing, const float* xs, const float* ys,
								 const float* zs) const;

	size_t occupiedLeaves() const { return leaves_; }  // 0 without a tree

	/** Grids with fewer voxels get no tree (a single scan): rows are searched directly. */
	static constexpr size_t kTreeFromVoxels = 65536;

   private:
	/** The voxel rows under the tree's occupied leaves within [lo, hi], as
	 *  spans in ascending key order. */
	std::vector<VoxelGrid::KeySpan> rowsUnderOccupiedLeaves(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const;

	const VoxelGrid& grid_;
	GatherParams params_;
	std::unique_ptr<octomap::OcTree> tree_;
	size_t leaves_ = 0;
};

}  // namespace tagmap
