// Time-stamped sensor poses and the TUM text format ("t x y z qx qy qz qw",
// one pose per line), the format of the simulator's trajectory_*.tum and of
// the usual trajectory evaluation tools.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tagmap::localize
{
struct StampedPose
{
	double stamp = 0;  // seconds
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // T_G_sensor
};

using Trajectory = std::vector<StampedPose>;

/** Throws InputError naming the file and line on anything but TUM lines;
 *  blank lines and '#' comments are skipped. */
Trajectory readTum(const std::string& path);

/** The sensor positions of a TUM file (its frame), for the front side's
 *  lines of sight (`detect --viewpoints`). Throws InputError when it holds
 *  no pose: an empty trajectory is a mistake, not "no viewpoint". */
std::vector<Eigen::Vector3d> readTumPositions(const std::string& path);

std::string toTum(const Trajectory& trajectory);

/** Writes toTum() atomically. */
void writeTum(const std::string& path, const Trajectory& trajectory);

}  // namespace tagmap::localize
