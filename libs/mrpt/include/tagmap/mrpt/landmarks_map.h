// Tags as an mrpt::maps::CLandmarksMap: one featBeacon landmark per tag, so
// MRPT's own range-only machinery (pf-localization, ro-localization,
// CMultiMetricMap) can use a tag map without knowing about tags.
#pragma once

#include <mrpt/maps/CLandmarksMap.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_bridge
{
/** Landmark of one tag: ID = encodeBeaconId(family, id) (beacon_id.h),
 *  pose_mean = tag centre, normal = tag z axis (out of the printed face),
 *  pose_cov = the position block of the tag covariance. */
mrpt::maps::CLandmark tagToLandmark(const TagDetection& tag);

/** All tags, in the given order. */
mrpt::maps::CLandmarksMap tagsToLandmarksMap(const std::vector<TagDetection>& tags);

/** Writes tagsToLandmarksMap() as gz-compressed MRPT serialization,
 *  atomically (loads with CFileGZInputStream + archiveFrom(f) >> map). */
void writeLandmarksMap(const std::string& path, const std::vector<TagDetection>& tags);

}  // namespace tagmap::mrpt_bridge
