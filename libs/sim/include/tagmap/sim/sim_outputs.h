// Writing a simulation to disk: DIR/map.pcd (binary, via tagmap::io),
// DIR/ground_truth.json (the `tags` schema of docs/RESULT_FORMAT.md + scene metadata) and
// optionally the SLAM-style keyframes DIR/scans.simplemap and the
// trajectories DIR/trajectory_true.tum and DIR/trajectory_drifted.tum.
#pragma once

#include <mrpt/maps/CSimpleMap.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "tagmap/sim/simulate.h"

namespace tagmap::sim
{
struct WriteOptions
{
	bool simplemap = false;
	uint64_t seed = 0;  // recorded in the metadata
	/** Also DIR/map.las in this LAS point format (0..10); -1: none. */
	int lasFormat = -1;
	/** Added to map.pcd (then float64 x y z), map.las and ground_truth.json:
	 *  a georeferenced copy of the scene (e.g. UTM), for testing large
	 *  coordinates. The simplemap and trajectories stay unshifted. */
	Eigen::Vector3d shift = Eigen::Vector3d::Zero();
	/** DIR/trajectory_true.tum and DIR/trajectory_drifted.tum (the frames'
	 *  sensor poses in the map's frame, as SLAM writes them beside a map;
	 *  always with the simplemap). */
	bool trajectories = false;
};

/** Creates `dir` if needed; every file is written atomically. Throws InputError
 *  if the folder is not writable. */
void writeSimulationOutputs(const std::string& dir, const SimulationOutput& out, const WriteOptions& options);

/** Extra top-level JSON fields describing the run (points, sensors, frames,
 *  points per tag...), for writeTagsJson. */
std::string groundTruthMetadata(const SimulationOutput& out, uint64_t seed,
								const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());

/** One keyframe per frame: a CObservationPointCloud whose CPointsMapXYZI is in
 *  the sensor frame, at the frame's drifted pose (what a SLAM map holds). */
mrpt::maps::CSimpleMap toSimpleMap(const SimulationOutput& out);

/** "stamp tx ty tz qx qy qz qw" lines, one per frame. */
std::string tumTrajectory(const SimulationOutput& out, bool drifted);

}  // namespace tagmap::sim
