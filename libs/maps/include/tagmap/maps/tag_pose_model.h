// The algebra of a seen tag's 6-DoF pose against the mapped tag, shared by
// CTagMap's observation likelihood (CObservationTagPoses) and tagmap_localize's
// direct relocalization, so both floor covariances and measure residuals the
// same way.
//
// Conventions (TagDetection): covariance of [x y z | rx ry rz], translation
// added, rotation as a small-angle vector applied on the left in the frame the
// pose maps into ({G} for T_G_tag, the sensor frame for T_sensor_tag).
#pragma once

#include <Eigen/Geometry>

#include "tagmap/tag_detection.h"

namespace tagmap::maps
{
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

Eigen::Matrix3d skew(const Eigen::Vector3d& v);

/** The rotation vector (axis * angle) of R. */
Eigen::Vector3d rotationLog(const Eigen::Matrix3d& R);

/** The covariance, or a diagonal one of the given standard deviations where
 *  it is missing (not finite or a zero diagonal), with its diagonal raised to
 *  those standard deviations; `onlyIfMissing` leaves a present covariance as
 *  it is (map tags: their covariance is the map's own verdict). Metres,
 *  degrees. */
Matrix6d usableCovariance(const Matrix6d& c, double stdPos, double stdRotDeg, bool onlyIfMissing);

/** Standard deviations of the model, metres and degrees. */
struct TagPoseNoise
{
	double minSeenStdPosition = 0.002;  // floors on the seen tag's covariance
	double minSeenStdRotationDeg = 0.1;
	double mapTagStdPosition = 0.005;  // a map tag without a covariance
	double mapTagStdRotationDeg = 0.3;
	/** Added on top (e.g. a particle filter's belief spread while it is
	 *  global); the rotation also moves the tag by its lever arm (range). */
	double extraStdPosition = 0;
	double extraStdRotationDeg = 0;
};

struct TagPoseResidual
{
	Vector6d residual = Vector6d::Zero();  // seen - predicted, sensor frame
	Matrix6d covariance = Matrix6d::Identity();  // of the residual, sensor frame
	/** residual' covariance^-1 residual */
	double mahalanobis2() const { return residual.dot(covariance.ldlt().solve(residual)); }
};

/** The seen tag (`seen.pose` = T_sensor_tag) against its prediction
 *  T_G_sensor^-1 * T_G_tag (`mapTag.pose` = T_G_tag): residual and its
 *  covariance, the seen tag's (floored) plus the map tag's rotated into the
 *  sensor frame plus the extra terms. */
TagPoseResidual tagPoseResidual(const Eigen::Isometry3d& T_G_sensor, const TagDetection& mapTag,
								const TagDetection& seen, const TagPoseNoise& noise);

}  // namespace tagmap::maps
