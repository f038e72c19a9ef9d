// Stage 6d: which side of a decoded sheet is its printed face. A LiDAR sees
// a tag from the free space in front of it; the wall, pillar or board that
// holds it lies behind. The decoder reads every quad as seen from both sides
// (the box's normal has no preferred sign), and the side it read from sets
// the tag's +z (docs/RESULT_FORMAT.md: out of the printed face). A read whose
// +z points into a solid body, with free space on the other side, is the
// mirror image of what is printed: a mirror-printed tag, a pattern seen
// through a window, or a chance read of the wrong side. It is no tag.
//
// The evidence is the map itself: the columns of space straight in front of
// and behind the tag's square, to a depth of a few tag sizes. A column is
// blocked when it holds map points beyond the tag's own noisy surface. Only
// a clear case decides (the front mostly blocked, the back almost all
// free); a one-sided wall scan (nothing behind, nothing in front) or
// clutter on both sides leaves the read as it is.
//
// Where the map says where its sensors stood (a .simplemap's or .rawlog's
// observations), the lines of sight decide that one-sided case too: a LiDAR
// measures a tag along straight, unobstructed lines from its position, so
// the printed face must see one of them (seenOnlyFromBehind()).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tagmap/tag_detection.h"
#include "tagmap/voxel_grid.h"

namespace tagmap
{
struct FrontSideParams
{
	bool enabled = true;
	/** How far to look on each side of the tag, in tag sizes: a pillar or
	 *  box behind a tag is typically one to a few tags deep. */
	double depthSizes = 3.0;
	/** Columns across the tag's square per side (a grid of columns x
	 *  columns over its inner 80 %, clear of its border's mixed pixels). */
	int columns = 5;
	/** The printed face looks into a solid body when at least this fraction
	 *  of its columns are blocked... */
	double blockedFraction = 0.5;
	/** ...while at most this fraction behind it are: the free space the
	 *  sensor saw the tag from. */
	double freeFraction = 0.1;
};

struct FrontSideEvidence
{
	double blockedInFront = 0;  // fraction of columns on the tag's +z side with points
	double blockedBehind = 0;  // the same on its -z side
};

/** The blocked fractions on both sides of `t` from `around` (map indices
 *  near the tag: gathered in a box reaching depthSizes x size on both
 *  sides). Points within `surface` of the tag's plane (its own noisy
 *  surface, a wall it is stuck on) belong to neither side. */
FrontSideEvidence measureFrontSide(const TagDetection& t, const std::vector<uint32_t>& around, const float* xs,
								   const float* ys, const float* zs, double surface, const FrontSideParams& p);

/** True when the evidence says the read's printed face looks into a solid
 *  body with free space behind it (the read is the sheet's mirror image). */
bool printedFaceLooksIntoSolid(const FrontSideEvidence& e, const FrontSideParams& p);

/** True when the sensors saw only the back of `t`'s sheet: no straight line
 *  from just off its printed face (+z) to a viewpoint on that side is clear
 *  of the map's occupied voxels (`grid`), while one from just off its back
 *  to a viewpoint on the other side is. The read is then the mirror image of
 *  what is printed: a mirror-printed sheet on a wall scanned from one side,
 *  a tag seen through glass. `viewpoints`: where the sensors stood, in the
 *  map frame; none, and nothing is known (false). `clearance`: how far off
 *  the sheet the lines start, past the voxels of its own points. */
bool seenOnlyFromBehind(const TagDetection& t, const std::vector<Eigen::Vector3d>& viewpoints, const VoxelGrid& grid,
						double clearance);

}  // namespace tagmap
