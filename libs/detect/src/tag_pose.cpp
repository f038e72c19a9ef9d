#include "tagmap/tag_pose.h"

#include <cmath>

namespace tagmap
{
Eigen::Matrix<double, 6, 6> tagFrameCovarianceToMap(const Eigen::Matrix3d& R, const Eigen::Vector3d& sigmaT,
													 const Eigen::Vector3d& sigmaR)
{
	Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
	C.topLeftCorner<3, 3>() = R * sigmaT.cwiseAbs2().asDiagonal() * R.transpose();
	C.bottomRightCorner<3, 3>() = R * sigmaR.cwiseAbs2().asDiagonal() * R.transpose();
	return C;
}

TagDetection solveTagPose(const DecodedTag2D& decoded, const PlaneImage& plane, double knownSize)
{
	TagDetection t;
	t.family = decoded.family;
	t.id = decoded.id;
	t.decodeMargin = decoded.margin;
	t.mirrored = decoded.mirrored;
	for (int k = 0; k < 4; k++) t.corners[k] = plane.frame.toMap(decoded.corners[k]);
	t.pose = poseFromCorners(t.corners);

	// The corners are on the plane by construction, but Kabsch on four
	// corners alone tilts with corner noise; the plane normal from every
	// point on the tag is far better, so rotate the pose onto it.
	const Eigen::Vector3d n = plane.frame.n * (plane.frame.n.dot(t.pose.linear().col(2)) >= 0 ? 1 : -1);
	Eigen::Vector3d x = t.pose.linear().col(0);
	x = (x - n * n.dot(x)).normalized();
	t.pose.linear().col(0) = x;
	t.pose.linear().col(1) = n.cross(x);
	t.pose.linear().col(2) = n;

	double measured = 0;
	for (int k = 0; k < 4; k++) measured += (t.corners[(k + 1) % 4] - t.corners[k]).norm() / 4;
	t.size = knownSize > 0 ? knownSize : measured;
	t.corners = cornersFromPose(t.pose, t.size);
	t.pointsUsed = static_cast<int>(plane.inliers.size());

	// First-order uncertainty: a corner is located to about half a pixel;
	// the plane from N points with residual RMS.
	const double sc = 0.5 * plane.frame.pixel;
	const double N = std::max<double>(1.0, static_cast<double>(plane.inliers.size()));
	const double sPlane = plane.planeRms / std::sqrt(N);
	const double sTilt = plane.planeRms / (0.5 * t.size * std::sqrt(N / 3.0));
	t.covariance = tagFrameCovarianceToMap(t.pose.linear(), Eigen::Vector3d(sc / 2, sc / 2, sPlane),
										   Eigen::Vector3d(sTilt, sTilt, sc / (t.size * std::sqrt(2.0))));
	return t;
}

}  // namespace tagmap
