// A rawlog written by `tagmap observe`, as the steps a localizer runs:
// one per scan, with the odometry since the previous scan and what the scan
// saw of the tags. Either rawlog format: odometry from the actions
// (CActionRobotMovement2D or 3D) or, in an observations-only rawlog, from
// CObservationOdometry (the increments between consecutive readings). A
// rawlog with movement actions uses those only, so odometry stored both ways
// is not counted twice.
#pragma once

#include <mrpt/obs/CObservationBeaconRanges.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <vector>

#include "tagmap/obs/CObservationTagPoses.h"

namespace tagmap::localize
{
struct LocalizationStep
{
	double stamp = 0;  // seconds (the scan's time stamp)
	/** Odometry since the previous step, on the ground plane: every movement
	 *  in between, composed (zero if none). Only the mean: the rawlog's motion
	 *  model is not used (how much to trust odometry is a localizer setting),
	 *  and the mean of a Thrun-model PDF is that of random samples, drawn
	 *  again whenever MRPT loads the rawlog: runs would differ. */
	mrpt::poses::CPose2D odometry;
	mrpt::obs::CObservationBeaconRanges::Ptr ranges;  // never null (may hold no range)
	obs::CObservationTagPoses::Ptr tags;  // never null (may hold no tag)
	mrpt::poses::CPose3D sensorPose;  // the LiDAR on the robot
};

enum class OdometryUse
{
	optional,  // read it if there is any (direct relocalization needs none)
	required,  // a rawlog without any is an InputError (the particle filter)
	ignored  // every step's odometry is zero (an odometry-free filter)
};

/** Throws InputError (naming `sourceName`) if the rawlog has no
 *  CObservationTagPoses at all, i.e. `tagmap observe` did not run on it, or
 *  if odometry is required and the rawlog has none. */
std::vector<LocalizationStep> localizationSteps(const mrpt::obs::CRawlog& log, const std::string& sourceName,
												OdometryUse odometry = OdometryUse::optional);

}  // namespace tagmap::localize
