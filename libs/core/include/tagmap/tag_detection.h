// One tag found in (or placed into) a map: the `tags` schema of
// docs/RESULT_FORMAT.md as a C++ value.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

namespace tagmap
{
struct TagDetection
{
	std::string family;
	int id = -1;
	double size = 0;  // border-square edge, metres

	/** Vertex-index order: 0 top-left, 1 top-right, 2 bottom-right,
	 *  3 bottom-left of the upright pattern seen from the front, in {G}. */
	std::array<Eigen::Vector3d, 4> corners;

	/** T_G_tag: map <- tag. Origin at the border-square centre. */
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();

	/** Covariance of [x y z | rx ry rz] (rotation as a small-angle vector in
	 *  the map frame, applied on the left), metres and radians. */
	Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();

	// Diagnostics (optional in the JSON schema).
	int pointsUsed = 0;  // raw map points on the tag plane used for the pose
	double decodeMargin = 0;  // decoder's confidence (libapriltag decision margin / ArUco)
	double patternFit = 0;  // correlation of the points with the tag bitmap, 0..1
	/** Points the pattern fit correlated: how sure patternFit is (the merge
	 *  compares two readings of one square by it). Not written out. */
	int patternPoints = 0;
	bool mirrored = false;  // decoded on the mirrored image (tag seen from "behind" its box)

	Eigen::Vector3d position() const { return pose.translation(); }
	Eigen::Quaterniond quaternion() const { return Eigen::Quaterniond(pose.linear()); }
};

/** "family:id", the label a tag goes by in reports, views and summaries. */
inline std::string tagLabel(const std::string& family, int id) { return family + ":" + std::to_string(id); }

/** The 4 corners of a tag of edge `size` in its own frame, in vertex order. */
std::array<Eigen::Vector3d, 4> tagModelCorners(double size);

/** Pose T_G_tag and size from 4 corners in vertex order (least squares). */
Eigen::Isometry3d poseFromCorners(const std::array<Eigen::Vector3d, 4>& corners);

/** Corners in {G} from a pose and a size. */
std::array<Eigen::Vector3d, 4> cornersFromPose(const Eigen::Isometry3d& T_G_tag, double size);

/** Roll, pitch, yaw (XYZ fixed axes, i.e. R = Rz(yaw) Ry(pitch) Rx(roll)), radians. */
Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& R);

}  // namespace tagmap
