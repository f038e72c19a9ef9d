// Tags as keys of an MRPT ini section, so a [MetricMap] file can carry a
// complete tag map (CTagMap's TMapDefinition reads them back):
//   tag_count=N
//   tag_001_family=tag36h11   tag_001_id=3   tag_001_size=0.164
//   tag_001_pose=x y z qw qx qy qz      (T_G_tag, metres)
//   tag_001_cov=36 numbers, row-major  (optional; zero when absent)
// Numbering starts at 1 and uses %03u, like CLandmarksMap's beacon_%03u keys.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_bridge
{
/** Writes the keys (no section header) for `tags`. */
void writeTagsIniKeys(std::ostream& out, const std::vector<TagDetection>& tags);

/** Reads them back; throws tagmap::InputError naming the section and key on
 *  a missing or malformed value. Corners are rebuilt from pose and size. */
std::vector<TagDetection> readTagsIniKeys(const mrpt::config::CConfigFileBase& ini, const std::string& section);

}  // namespace tagmap::mrpt_bridge
