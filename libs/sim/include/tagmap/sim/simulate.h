// The simulator's entry point: a Scene in, a merged LiDAR map, the per-frame
// scans (true and drifted poses) and exact tag ground truth out.
//
//   auto scene = tagmap::sim::loadScene("share/scenes/accuracy.yaml", {{"tag_distance", 4.0}});
//   tagmap::sim::SimOptions opt;
//   opt.seed = 7;
//   auto out = tagmap::sim::simulate(scene, opt);   // out.map, out.truth, out.frames
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "tagmap/count_progress.h"
#include "tagmap/sim/scene.h"
#include "tagmap/tag_detection.h"

namespace tagmap::sim
{
struct SimOptions
{
	uint64_t seed = 1;
	/** Full-scale intensity of the output (1, 255, 65535...). Only multiplies
	 *  the written intensities; rays and noise are identical for any value. */
	double intensityScale = 1.0;
	unsigned threads = 0;  // 0 = all hardware threads
	/** > 0: rescale every sensor's density (grid step, point rate, columns)
	 *  so the map has about this many points (measured by a pilot run). */
	size_t targetPoints = 0;
	/** Rays per work unit and random stream. Fixed, not derived from the
	 *  thread count, so results are identical for any number of threads. */
	size_t blockRays = 8192;
};

/** One simulated point in its frame (sensor frame at the frame's reference time). */
struct SimPoint
{
	Eigen::Vector3f local;
	float intensity01 = 0;  // before the output scale
	int32_t object = -1;  // index into SimulationOutput::objectNames (-1: none)
};

struct FrameData
{
	int run = 0;
	std::string runName, sensorName;
	double time = 0;  // run-relative reference time of the frame, seconds
	double stamp = 0;  // the same on the scene's single sensor clock (increasing over runs)
	double duration = 0;
	Eigen::Isometry3d truePose = Eigen::Isometry3d::Identity();  // world <- sensor
	Eigen::Isometry3d driftedPose = Eigen::Isometry3d::Identity();  // as a SLAM map would have it
	Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();  // carrier <- sensor (ScanRun::mount)
	size_t firstPoint = 0, pointCount = 0;  // range in SimulationOutput::points
};

/** How the scans saw one tag: the conditions a missed tag is explained by
 *  (ground_truth.json writes them per tag). */
struct TagSighting
{
	size_t points = 0;  // points whose echo came mostly from the tag's paper
	size_t pointsInSquare = 0;  // of those, inside the black border square
	double pointsPerCell = 0;  // pointsInSquare per cell of the border square
	int scans = 0;  // frames with a point on the paper
	double rangeMin = 0, rangeMax = 0;  // metres from the sensor, over those points (0: none)
	double incidenceDegMin = 0;  // smallest angle between a ray and the tag's normal
};

struct SimulationOutput
{
	std::string sceneName;
	std::vector<std::string> sensorNames;
	std::vector<std::string> objectNames;  // scene objects, then one paper per tag
	std::vector<TagDetection> truth;  // printed faces in {G}, vertex order of docs/RESULT_FORMAT.md
	std::vector<TagSighting> tagSightings;  // one per truth tag
	/** Each tag where the drifted map shows it: the true pose moved by the
	 *  drift of the frame that saw most of it (T_drifted_k * T_true_k^-1).
	 *  Equals `truth` without drift; tells map error from detector error. */
	std::vector<TagDetection> truthInMap;
	std::vector<FrameData> frames;
	std::vector<SimPoint> points;  // grouped by frame
	/** All frames merged at their drifted poses, intensities x intensityScale. */
	mrpt::maps::CPointsMapXYZI map;
	double intensityScale = 1;
	double densityFactor = 1;  // applied to the sensors (targetPoints)
	size_t raysCast = 0;
	double seconds = 0;
};

/** `progress`: rays cast so far and in all; called from worker threads,
 *  serialized, with non-decreasing counts (a block of rays at a time). */
SimulationOutput simulate(const Scene& scene, const SimOptions& options = {}, const CountProgressFn& progress = {});

}  // namespace tagmap::sim
