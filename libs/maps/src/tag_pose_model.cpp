#include "tagmap/maps/tag_pose_model.h"

#include <algorithm>
#include <cmath>

namespace tagmap::maps
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}

Eigen::Vector3d rotationLog(const Eigen::Matrix3d& R)
{
	const Eigen::AngleAxisd aa(R);
	return aa.angle() * aa.axis();
}

Matrix6d usableCovariance(const Matrix6d& c, double stdPos, double stdRotDeg, bool onlyIfMissing)
{
	const double vp = stdPos * stdPos, vr = std::pow(stdRotDeg * M_PI / 180, 2);
	Matrix6d out = c;
	if (!c.allFinite() || c.diagonal().isZero(0)) out.setZero();
	else if (onlyIfMissing)
		return out;
	for (int i = 0; i < 6; i++) out(i, i) = std::max(out(i, i), i < 3 ? vp : vr);
	return out;
}

TagPoseResidual tagPoseResidual(const Eigen::Isometry3d& T_G_sensor, const TagDetection& mapTag,
								const TagDetection& seen, const TagPoseNoise& noise)
{
	const Eigen::Isometry3d predicted = T_G_sensor.inverse() * mapTag.pose;  // T_sensor_tag
	TagPoseResidual r;
	r.residual.head<3>() = seen.pose.translation() - predicted.translation();
	r.residual.tail<3>() = rotationLog(seen.pose.linear() * predicted.linear().transpose());

	// Perturbing T_G_tag by (dt, dr) in {G} moves the prediction by
	// (R' dt, R' dr) in the sensor frame, R = R_G_sensor.
	const Eigen::Matrix3d Rt = T_G_sensor.linear().transpose();
	Matrix6d J = Matrix6d::Zero();
	J.block<3, 3>(0, 0) = Rt;
	J.block<3, 3>(3, 3) = Rt;
	const Matrix6d Cg = usableCovariance(mapTag.covariance, noise.mapTagStdPosition, noise.mapTagStdRotationDeg, true);
	r.covariance = usableCovariance(seen.covariance, noise.minSeenStdPosition, noise.minSeenStdRotationDeg, false) +
				   J * Cg * J.transpose();

	const double extraRot = noise.extraStdRotationDeg * M_PI / 180;
	const double lever = extraRot * predicted.translation().norm();
	const double extraPosVar = noise.extraStdPosition * noise.extraStdPosition + lever * lever;
	for (int i = 0; i < 3; i++)
	{
		r.covariance(i, i) += extraPosVar;
		r.covariance(i + 3, i + 3) += extraRot * extraRot;
	}
	return r;
}

}  // namespace tagmap::maps
