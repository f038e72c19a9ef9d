#include "tagmap/tag_pose.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "tagmap/point_stats.h"
#include "tagmap/tag_family.h"

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

void setTagFrameCovariance(Eigen::Matrix<double, 6, 6>& C, const Eigen::Matrix3d& R, bool rotation,
						   const std::vector<int>& axes, const Eigen::MatrixXd& block)
{
	const int at = rotation ? 3 : 0;
	Eigen::Matrix3d inTag = R.transpose() * C.block<3, 3>(at, at) * R;
	for (int a : axes)
		for (int other = 0; other < 3; other++)
			if (std::find(axes.begin(), axes.end(), other) == axes.end()) inTag(a, other) = inTag(other, a) = 0;
	for (size_t i = 0; i < axes.size(); i++)
		for (size_t j = 0; j < axes.size(); j++)
			inTag(axes[i], axes[j]) = block(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
	C.block<3, 3>(at, at) = R * inTag * R.transpose();
}

double measuredTagSize(const Quad& corners, const PlaneImage& plane)
{
	double side = 0;
	for (int k = 0; k < 4; k++) side += (corners[(k + 1) % 4] - corners[k]).norm() / 4;
	return side * plane.frame.pixel;
}

double measuredTagSize(const DecodedTag2D& decoded, const PlaneImage& plane)
{
	return measuredTagSize(decoded.corners, plane);
}

OrientedBox wholeGridBox(const DecodedTag2D& decoded, const PlaneImage& plane)
{
	const Quad& c = decoded.corners;
	const TagBitmap grid = renderTagBitmap(decoded.family, 0);  // the same grid for every id
	const double across = measuredTagSize(decoded, plane) * grid.cells / grid.borderCells;
	OrientedBox box;
	box.center = plane.frame.toMap(0.25 * (c[0] + c[1] + c[2] + c[3]));
	const Eigen::Vector3d along = (plane.frame.toMap(c[1]) - plane.frame.toMap(c[0])).normalized();
	box.axes.col(0) = along;
	box.axes.col(1) = plane.frame.n.cross(along);
	box.axes.col(2) = plane.frame.n;
	box.extent = Eigen::Vector3d(across, across, 0);
	return box;
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

	t.size = knownSize > 0 ? knownSize : measuredTagSize(decoded, plane);
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

void refitTagPlane(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs)
{
	const Eigen::Isometry3d inv = t.pose.inverse();
	const double half = 0.5 * t.size;
	std::vector<uint32_t> on;
	std::vector<double> depth;
	for (uint32_t i : plane.inliers)
	{
		const Eigen::Vector3d l = inv * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		if (std::abs(l.x()) <= half && std::abs(l.y()) <= half) on.push_back(i);
	}
	if (on.size() < 20) return;
	PointStats st;
	Eigen::Vector3d n = t.pose.linear().col(2);
	double rms = 0;
	// Two trimmed rounds: drop the few mixed-pixel points beyond 3 sigma.
	for (int round = 0; round < 2; round++)
	{
		st = pointStats(xs, ys, zs, on);
		Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(st.scatter);
		n = es.eigenvectors().col(0);
		if (n.dot(t.pose.linear().col(2)) < 0) n = -n;
		rms = std::sqrt(std::max(0.0, es.eigenvalues()(0)) / static_cast<double>(on.size()));
		std::vector<uint32_t> kept;
		for (uint32_t i : on)
			if (std::abs((Eigen::Vector3d(xs[i], ys[i], zs[i]) - st.mean).dot(n)) <= 3 * rms + 1e-9) kept.push_back(i);
		if (kept.size() < 20) break;
		on.swap(kept);
	}
	// Smallest rotation taking the old normal onto the new one; the centre
	// moves along the normal onto the new plane.
	const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(t.pose.linear().col(2), n).toRotationMatrix();
	t.pose.linear() = R * t.pose.linear();
	const Eigen::Vector3d c = t.pose.translation();
	t.pose.translation() = c - n * n.dot(c - st.mean);
	t.corners = cornersFromPose(t.pose, t.size);
	t.pointsUsed = static_cast<int>(on.size());
	const double N = static_cast<double>(on.size());
	const double sTilt = rms / (0.5 * t.size * std::sqrt(N / 3.0));
	setTagFrameCovariance(t.covariance, t.pose.linear(), false, {2}, Eigen::Matrix<double, 1, 1>(rms * rms / N));
	setTagFrameCovariance(t.covariance, t.pose.linear(), true, {0, 1},
						  Eigen::Matrix2d(Eigen::Vector2d::Constant(sTilt * sTilt).asDiagonal()));
}

}  // namespace tagmap
