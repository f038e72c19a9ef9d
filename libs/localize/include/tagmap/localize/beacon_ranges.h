// Seen tags as an MRPT CObservationBeaconRanges: the range from the LiDAR to
// each tag centre, keyed by the landmark beacon ID (tagmap/mrpt/beacon_id.h),
// so MRPT's range-only machinery (CLandmarksMap / CBeaconMap likelihoods,
// pf-localization) can use tag detections without knowing about tags.
#pragma once

#include <mrpt/obs/CObservationBeaconRanges.h>
#include <mrpt/poses/CPose3D.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
struct BeaconRangeParams
{
	/** Floor on the reported standard deviation, metres: the covariance of a
	 *  sparse-scan detection can be overconfident. */
	double minStd = 0.01;
	double maxRange = 100;  // metres, stored as the sensor's maxSensorDistance
};

/** `tags` in the sensor frame (T_sensor_tag); `sensorPose` = the LiDAR on
 *  the robot. stdError = the largest per-tag range std, sqrt(u' C u) with u
 *  the unit vector to the tag centre and C its position covariance (one
 *  stdError per observation is all MRPT stores). Tags of families without a
 *  beacon index are left out. */
mrpt::obs::CObservationBeaconRanges::Ptr makeBeaconRanges(const std::vector<TagDetection>& tags,
														   const mrpt::poses::CPose3D& sensorPose,
														   const BeaconRangeParams& params = {});

}  // namespace tagmap::localize
