// Sensor poses over time and the cutting of runs into frames (the unit a
// SLAM front-end registers: one sweep, one revolution, one 0.1 s Livox frame).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
/** Pose at run-relative time t: linear in position, slerp in rotation,
 *  clamped to the first/last waypoint. */
Eigen::Isometry3d interpolatePose(const std::vector<Waypoint>& waypoints, double t);

/** The run's sensor at run-relative time t: the carrier's pose, then the mount. */
Eigen::Isometry3d sensorPoseAt(const ScanRun& run, double t);

struct Frame
{
	int run = 0;
	int sensor = 0;
	double t0 = 0;  // run-relative start time (for the pose)
	double clock = 0;  // absolute sensor clock at the start (for the scan pattern's phase)
	double duration = 0;  // 0 for a terrestrial station
	double tRef = 0;  // run-relative time the frame's points are expressed at (mid-frame)
	Eigen::Isometry3d truePose = Eigen::Isometry3d::Identity();  // world <- sensor at tRef
	bool moving = false;  // pose changes during the frame
	size_t rays = 0;
};

/** Frames of every run in scene order. Grid sensors: one frame per waypoint
 *  (station). Others: frames of the sensor's frame period covering the
 *  run (the last one shortened), `duration` seconds for a single waypoint.
 *  Runs follow each other on one sensor clock. */
std::vector<Frame> scheduleFrames(const Scene& scene);

/** Seconds per frame for a continuously scanning sensor. */
double framePeriod(const SensorSpec& s);

}  // namespace tagmap::sim
