// Stage 6c: the tag's orientation from the tag and the flat surface it is
// stuck on. With 2 cm range noise a tag's own ~2000 points fix its normal
// to ~0.5 deg; the wall, board or pillar face around it is the same plane
// and holds several times the points at several times the lever arm. The
// region grows ring by ring outwards from the tag's border and stops at the
// first ring that is not the same plane (a board's edge standing off the
// wall, a tilted board, a pillar's corner): a ring whose mean offset or
// slope against the plane so far exceeds `stepSigmas` standard errors (the
// errors of independent noise, inflated by how much more the slopes of the
// tag's own quadrants scatter than that: scan lines and beam footprints
// correlate neighbouring points). The
// tag's position along the normal still comes from its own points only.
#pragma once

#include <cstdint>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
struct SupportPlaneParams
{
	bool enabled = true;
	/** Half-width of the largest region, in tag sizes from the centre
	 *  (1.5: a square three tags across). */
	double reachSizes = 1.5;
	/** A ring is another surface when its offset or slope against the plane
	 *  fitted so far exceeds this many standard errors. */
	double stepSigmas = 3.0;
};

/** Tilts t.pose onto the plane of the tag and its coplanar surroundings
 *  among `around` (map indices near the tag, e.g. gathered in a box of
 *  half-width reachSizes x size); updates corners, pointsUsed and the
 *  tilt and normal-offset covariance. Returns the region's half-width in
 *  tag sizes (0.5: only the tag itself was flat enough). */
double fitSupportPlane(TagDetection& t, const std::vector<uint32_t>& around, const float* xs, const float* ys,
					   const float* zs, const SupportPlaneParams& p);

}  // namespace tagmap
