// The lengths the pipeline derives from the map's measured point spacing,
// named once with the reason for each. Parameters are in point spacings so
// that no sensor constant is needed; these are the metres the stages get.
#pragma once

#include <algorithm>

#include "tagmap/pipeline_params.h"

namespace tagmap
{
struct DerivedLengths
{
	/** Median nearest-neighbour distance of the map (point_spacing.h). */
	double spacing = 0;
	/** The intensity gradient's neighbourhood radius r
	 *  (gradient_radius_spacings x spacing): enough neighbours for a
	 *  least-squares slope, small enough to resolve a tag's cells. */
	double gradientRadius = 0;
	/** The neighbour index's voxel edge: r, so that a point's neighbours
	 *  within r all lie in its voxel's 3x3x3 block. */
	double voxelCell = 0;
	/** The occupancy octree's leaf edge: gather.octree_cells_per_leaf
	 *  voxels. Coarse enough that the tree stays a fraction of the index
	 *  (one leaf per up to 4^3 occupied voxels), fine enough that a gather
	 *  box skips the empty space of a room at a tag's scale. */
	double octreeLeaf = 0;
	/** How far a candidate's box may reach beyond the tag's border: kept
	 *  edge points lie up to r outside the black border ring, so the size
	 *  criterion allows the box this much wider on each side. */
	double candidateBand = 0;
	/** How far a flat surface's points stray from its plane: 3x the
	 *  map's measured surface noise (surface_noise.h: range noise, beam
	 *  footprint, drift between passes), at least 2 spacings (a noiseless
	 *  map's own sampling). The flatness criterion allows it twice. */
	double planeNoise = 0;

	static DerivedLengths of(double spacing, const PipelineParams& p)
	{
		DerivedLengths d;
		d.spacing = spacing;
		d.gradientRadius = p.gradientRadiusSpacings * spacing;
		d.voxelCell = d.gradientRadius;
		d.octreeLeaf = p.gather.octreeCellsPerLeaf * d.voxelCell;
		d.candidateBand = d.gradientRadius;
		d.planeNoise = 2 * spacing;
		return d;
	}

	/** Once the surface noise is measured (it needs the neighbour index,
	 *  which needs voxelCell): the plane noise follows it. */
	void setSurfaceNoise(double noise) { planeNoise = std::max(2 * spacing, 3 * noise); }
};

}  // namespace tagmap
