// Stage 1b: how thick the map's surfaces are. Range noise, beam footprint
// and the drift between merged passes spread a flat wall over a slab; the
// flatness test must allow that slab, whatever the sensor, or a real tag in
// a 2 cm-noise scan is rejected as "not flat". Measured, not configured:
// the median, over sample points, of the plane-fit RMS of their
// neighbourhoods (most of any map is locally flat: walls, floors, boards;
// corners and vegetation are the minority the median ignores).
#pragma once

#include <cstddef>

#include "tagmap/voxel_grid.h"

namespace tagmap
{
struct SurfaceNoiseParams
{
	/** Sample points, evenly strided through the map. The thresholds take
	 *  a few noise levels each, so the median of 1000 is ample: 2000 gave
	 *  the same tags on every map and scan measured, at twice the cost
	 *  (1.9 of a 25 k-point scan's 16 ms). At most as many as the points
	 *  hold neighbourhoods apart (n over a pilot's mean neighbours), at
	 *  least 200. */
	size_t samples = 1000;
	size_t minNeighbours = 12;	// fewer: no plane fitted at that sample
	/** A ball of radius R truncates a slab thicker than about R/2, so the
	 *  estimate is only trusted when below R / minRadiusOverNoise; else the
	 *  ball is doubled, at most maxDoublings times (each doubling halves
	 *  the samples: a ball 2x wider costs 8x the voxel lookups). */
	double minRadiusOverNoise = 4.0;
	int maxDoublings = 3;
};

/** Median plane-fit RMS (metres) of the neighbourhoods within a radius of
 *  grid.cellSize() (doubled while the slab fills the ball) around
 *  `p.samples` points; 0 when no sample has enough neighbours. */
double estimateSurfaceNoise(const float* xs, const float* ys, const float* zs, size_t n, const VoxelGrid& grid,
							const SurfaceNoiseParams& p = {});

}  // namespace tagmap
