#include "tagmap/localize/tag_relocalization.h"

#include <cmath>

#include "tagmap/maps/tag_pose_model.h"

namespace tagmap::localize
{
// The floors, skew and rotation log are shared with CTagMap's likelihood of
// CObservationTagPoses (tag_pose_model.h), so the PF and this agree.
using maps::rotationLog;
using maps::skew;
using maps::usableCovariance;

PoseWithCovariance sensorPoseFromTag(const TagDetection& mapTag, const TagDetection& seen,
									 const RelocalizationParams& params)
{
	const Eigen::Isometry3d T_s_tag = seen.pose;
	PoseWithCovariance out;
	out.pose = mapTag.pose * T_s_tag.inverse();
	const Eigen::Matrix3d R = out.pose.linear();  // R_G_sensor

	// Perturbing T_s_tag by (dt, dr):  T_G_s' has dr_G = -R dr and
	// dt_G = -R dt - R [t_s_tag]x dr.
	Matrix6d Js = Matrix6d::Zero();
	Js.block<3, 3>(0, 0) = -R;
	Js.block<3, 3>(0, 3) = -R * skew(T_s_tag.translation());
	Js.block<3, 3>(3, 3) = -R;
	// Perturbing T_G_tag by (dt, dr): dr_G = dr and dt_G = dt + [R t_s_tag]x dr.
	Matrix6d Jg = Matrix6d::Identity();
	Jg.block<3, 3>(0, 3) = skew(R * T_s_tag.translation());

	const Matrix6d Cs =
		usableCovariance(seen.covariance, params.minSeenStdPosition, params.minSeenStdRotationDeg, false);
	const Matrix6d Cg =
		usableCovariance(mapTag.covariance, params.mapTagStdPosition, params.mapTagStdRotationDeg, true);
	out.covariance = Js * Cs * Js.transpose() + Jg * Cg * Jg.transpose();
	return out;
}

std::optional<PoseWithCovariance> fusePoses(const std::vector<PoseWithCovariance>& poses, int iterations)
{
	if (poses.empty()) return std::nullopt;
	std::vector<Matrix6d> info;
	Matrix6d infoSum = Matrix6d::Zero();
	for (const auto& p : poses)
	{
		info.push_back(p.covariance.inverse());
		infoSum += info.back();
	}
	const Matrix6d covariance = infoSum.inverse();

	// Gauss-Newton on the weighted sum of squared tangent-space residuals,
	// starting from the first pose.
	Eigen::Isometry3d mean = poses.front().pose;
	for (int it = 0; it < iterations; it++)
	{
		Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
		for (size_t i = 0; i < poses.size(); i++)
		{
			Eigen::Matrix<double, 6, 1> r;
			r.head<3>() = poses[i].pose.translation() - mean.translation();
			r.tail<3>() = rotationLog(poses[i].pose.linear() * mean.linear().transpose());
			b += info[i] * r;
		}
		const Eigen::Matrix<double, 6, 1> d = covariance * b;
		mean.translation() += d.head<3>();
		const double angle = d.tail<3>().norm();
		if (angle > 0) mean.linear() = Eigen::AngleAxisd(angle, d.tail<3>() / angle).toRotationMatrix() * mean.linear();
	}
	return PoseWithCovariance{mean, covariance};
}

std::optional<PoseWithCovariance> relocalize(const std::vector<TagDetection>& map,
											 const std::vector<TagDetection>& seen, const RelocalizationParams& params,
											 size_t* used)
{
	std::vector<PoseWithCovariance> poses;
	for (const TagDetection& s : seen)
		for (const TagDetection& m : map)
			if (m.family == s.family && m.id == s.id)
			{
				poses.push_back(sensorPoseFromTag(m, s, params));
				break;
			}
	if (used) *used = poses.size();
	return fusePoses(poses, params.fusionIterations);
}

}  // namespace tagmap::localize
