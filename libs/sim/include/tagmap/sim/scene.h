// A simulated world as plain data: textured rectangles grouped into named
// objects (walls, boxes, tag papers, distractor posters), the sensors and
// the runs (trajectories or stations) that scan it. Loaded from YAML by
// scene_loader.h; turned into points by simulate.h.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "tagmap/sim/sensor_spec.h"
#include "tagmap/sim/texture.h"

namespace tagmap::sim
{
/** A bounded planar patch. Its frame: x = u (right), y = v (up), z = the
 *  normal of the printed face. */
struct Rect
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // world <- rect
	double halfW = 0, halfH = 0;
	Texture texture;
	/** Print (the grid) is on the front only; from behind a paper shows
	 *  its plain base reflectivity. */
	bool printedFrontOnly = false;
};

enum class ObjectKind
{
	Plane,
	Box,
	Tag,
	Distractor
};

struct SceneObject
{
	std::string name;
	ObjectKind kind = ObjectKind::Plane;
	std::vector<Rect> faces;
	int tagIndex = -1;  // into Scene::tags when kind == Tag
};

/** A printed tag. The paper is a Rect placed `paperOffset` in front of
 *  `pose` so it sits on, not in, the wall it is stuck to. */
struct TagSpec
{
	std::string family;
	int id = 0;
	double size = 0;  // border-square edge (docs/RESULT_FORMAT.md), metres
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // T_G_tag of the mounting surface
	double margin = 0.01;  // white paper beyond the bitmap's quiet-zone cell, metres
	double paperOffset = 1e-4;  // paper thickness/standoff from the wall, metres
	/** Random turn (from the seed) about the tag centre, degrees: in-plane
	 *  only for a tag stuck to a wall (it cannot tilt into it); about all
	 *  three axes when it is mounted on a board, which then leans on the
	 *  wall: lifted until its back corner nearest the wall touches it. */
	double jitterDeg = 0;
	/** Optional backing board (foam board) standing `boardStandoff` in front
	 *  of the mounting surface; the paper is glued on its front. */
	double boardWidth = 0, boardHeight = 0, boardStandoff = 0.02;
	float boardReflectivity = 0.6f;
	float black = 0.06f, white = 0.85f;  // ink / paper reflectivity
};

struct Waypoint
{
	double t = 0;  // seconds
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // world <- carrier (the sensor unless mounted)
};

/** One pass of one sensor: either stations (a terrestrial scanner, one sweep
 *  per waypoint; or a stationary LiDAR integrating `duration` seconds) or a
 *  timed trajectory cut into frames of the sensor's frame period. */
struct ScanRun
{
	std::string name;
	int sensor = 0;  // index into Scene::sensors
	std::vector<Waypoint> waypoints;
	double duration = 0;  // integration time at a single waypoint (stationary)
	double driftScale = 1;  // multiplies Scene::drift for this run
	/** Fraction of the intra-frame motion that deskewing fails to remove
	 *  (0 = perfect motion compensation, 1 = none) -> motion blur. */
	double deskewResidual = 0;
	/** The sensor on its carrier (`mount`: a robot base): the waypoints
	 *  move the carrier, the sensor rides at waypoint * mount. The rawlog's
	 *  odometry is then the carrier's and each scan's sensor pose this mount,
	 *  as a robot's driver writes them. Identity: the waypoints are the sensor. */
	Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
	/** Systematic odometry error of the carrier, on top of the random drift:
	 *  a wheel radius off by this fraction (every move's length scaled by
	 *  1 + it) and a wheelbase error that turns the heading this much per
	 *  metre driven. Wheel odometry has both; a random walk alone averages
	 *  out where a bias keeps pulling one way. */
	double odometryScaleError = 0;
	double odometryHeadingBiasDegPerM = 0;
};

/** SLAM-like drift of the poses used to merge frames: a random walk whose
 *  variance grows with distance travelled and with time. */
struct DriftParams
{
	double translationPerSqrtM = 0.002;  // metres per sqrt(metre travelled)
	double rotationDegPerSqrtM = 0.02;  // degrees per sqrt(metre travelled)
	double translationPerSqrtS = 0.0003;  // metres per sqrt(second)
	double rotationDegPerSqrtS = 0.003;  // degrees per sqrt(second)
};

struct Scene
{
	std::string name;
	std::string file;  // where it was loaded from ("" if built in code)
	std::vector<SceneObject> objects;
	std::vector<TagSpec> tags;
	std::vector<SensorSpec> sensors;
	std::vector<ScanRun> runs;
	DriftParams drift;
};

}  // namespace tagmap::sim
