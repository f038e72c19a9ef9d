// A simulation as an MRPT rawlog for localization: per frame, the robot's
// odometry since the previous frame (CActionRobotMovement2D) then its LiDAR
// scan (CObservationPointCloud, XYZI, points in the sensor frame).
//
// The robot frame is the true sensor pose projected onto the ground plane
// (x, y, yaw); each observation's sensorPose carries the rest (height, tilt),
// so robotPose (+) sensorPose is exactly the true sensor pose. The odometry
// is the drifted poses projected the same way: the scene's `drift` (and the
// run's drift_scale) is the odometry noise, seeded like the rest of the run.
#pragma once

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CRawlog.h>

#include <string>

#include "tagmap/sim/simulate.h"

namespace tagmap::sim
{
struct RawlogOptions
{
	/** The motion model stored with each odometry increment: what a particle
	 *  filter samples from. Should be at least as wide as the scene's drift. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel = defaultMotionModel();

	static mrpt::obs::CActionRobotMovement2D::TMotionModelOptions defaultMotionModel();
};

/** Action/sensory-frame rawlog, one pair per frame, in frame order. */
mrpt::obs::CRawlog toRawlog(const SimulationOutput& out, const RawlogOptions& options = {});

/** Writes toRawlog() to `path` (gz, atomically) and the true sensor poses,
 *  with the observations' time stamps, to `truthTumPath` (TUM). */
void writeSimulationRawlog(const std::string& path, const std::string& truthTumPath, const SimulationOutput& out,
						   const RawlogOptions& options = {});

}  // namespace tagmap::sim
