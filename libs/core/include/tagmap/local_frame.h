// Maps are detected in a local frame (file coordinates minus a whole-metre
// origin, io::LoadReport::origin) so that georeferenced coordinates keep
// millimetres in float32; results go back to the file's frame in double.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
/** The tags moved by `offset` (pose and corners): from a map's local frame
 *  back to its file's frame, or the other way with -offset. */
std::vector<TagDetection> translatedTags(std::vector<TagDetection> tags, const Eigen::Vector3d& offset);

}  // namespace tagmap
