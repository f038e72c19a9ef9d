#include "tagmap/tag_detection.h"

#include <Eigen/SVD>
#include <cmath>

namespace tagmap
{
std::array<Eigen::Vector3d, 4> tagModelCorners(double size)
{
	const double h = size / 2;
	return {Eigen::Vector3d(-h, h, 0), Eigen::Vector3d(h, h, 0), Eigen::Vector3d(h, -h, 0),
			Eigen::Vector3d(-h, -h, 0)};
}

Eigen::Isometry3d poseFromCorners(const std::array<Eigen::Vector3d, 4>& corners)
{
	// Kabsch/Umeyama without scale between the unit-size model and the corners;
	// the translation is the corner centroid (the model centroid is 0).
	Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
	for (const auto& c : corners) centroid += c / 4.0;
	const double size = 0.25 * ((corners[1] - corners[0]).norm() + (corners[2] - corners[1]).norm() +
								(corners[3] - corners[2]).norm() + (corners[0] - corners[3]).norm());
	const auto model = tagModelCorners(size);
	Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
	for (int i = 0; i < 4; i++) H += model[i] * (corners[i] - centroid).transpose();
	Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
	Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
	D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = svd.matrixV() * D * svd.matrixU().transpose();
	T.translation() = centroid;
	return T;
}

std::array<Eigen::Vector3d, 4> cornersFromPose(const Eigen::Isometry3d& T_G_tag, double size)
{
	auto c = tagModelCorners(size);
	for (auto& p : c) p = T_G_tag * p;
	return c;
}

Eigen::Vector3d rollPitchYaw(const Eigen::Matrix3d& R)
{
	const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
	const double yaw = std::atan2(R(1, 0), R(0, 0));
	const double roll = std::atan2(R(2, 1), R(2, 2));
	return {roll, pitch, yaw};
}

}  // namespace tagmap
