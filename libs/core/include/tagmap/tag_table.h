// Tags as a text table for people: one line per tag, position in metres,
// roll/pitch/yaw in degrees. The one printer behind `tagmap detect`'s
// terminal table, CTagMap::asString() and CObservationTagPoses'
// description in RawLogViewer, so all three read the same way.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
/** Optional columns; family, id, size, x y z and roll pitch yaw are always there. */
struct TagTableColumns
{
	/** A leading column (e.g. MRPT beacon IDs) with its header; unset: none. */
	std::string firstHeader;
	std::function<std::string(const TagDetection&)> first;
	bool range = false;  // distance of the tag centre from the frame origin (the sensor, for a scan)
	bool points = false;  // points used for the pose
	bool stdDev = false;  // standard deviations from the covariance: position in cm, angles in degrees
};

/** Header line and one line per tag, each ending in '\n'. */
std::string tagTable(const std::vector<TagDetection>& tags, const TagTableColumns& columns = {});

}  // namespace tagmap
