// Synthetic input for the MRPT integration tests: tags on a wall with known
// poses, and an XYZI map in which those tags are printed in the intensity
// channel (so viewers show recognisable patterns). No detection involved.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_test
{
/** Three tags of two families on the wall x = 5 m, facing the origin. */
std::vector<TagDetection> syntheticTags();

/** The wall (2 cm grid) with each tag's bitmap as intensity 0 / 255 and
 *  plain wall at 120. */
mrpt::maps::CPointsMapXYZI syntheticWallMap(const std::vector<TagDetection>& tags);

}  // namespace tagmap::mrpt_test
