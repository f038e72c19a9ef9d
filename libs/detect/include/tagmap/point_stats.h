// Mean and scatter of a subset of map points, shared by the box fit
// (clustering) and the plane fits (intermediate plane, sensor view).
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tagmap
{
struct PointStats
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();  // sum of outer products about the mean
};

inline PointStats pointStats(const float* xs, const float* ys, const float* zs, const std::vector<uint32_t>& pts)
{
	PointStats s;
	if (pts.empty()) return s;
	for (uint32_t i : pts) s.mean += Eigen::Vector3d(xs[i], ys[i], zs[i]);
	s.mean /= static_cast<double>(pts.size());
	// Six sums in registers, not a 3x3 matrix updated in memory: the
	// compiler spilled that one, and the reloads stalled on every point
	// (over half the time of rendering an intermediate plane). The same
	// products in the same order: the same result to the last bit.
	double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
	const double mx = s.mean.x(), my = s.mean.y(), mz = s.mean.z();
	for (uint32_t i : pts)
	{
		const double dx = xs[i] - mx, dy = ys[i] - my, dz = zs[i] - mz;
		xx += dx * dx, xy += dx * dy, xz += dx * dz, yy += dy * dy, yz += dy * dz, zz += dz * dz;
	}
	s.scatter << xx, xy, xz, xy, yy, yz, xz, yz, zz;
	return s;
}

/** Least-squares plane through a subset of map points: its centroid, unit
 *  normal (sign arbitrary) and the points' RMS distance from it. Shared by
 *  the intermediate plane and the sensor view's boxes. */
struct PlaneFit
{
	Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
	double rms = 0;
};

inline PlaneFit fitPlane(const float* xs, const float* ys, const float* zs, const std::vector<uint32_t>& pts)
{
	PlaneFit f;
	const PointStats st = pointStats(xs, ys, zs, pts);
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(st.scatter);
	f.centroid = st.mean;
	f.normal = es.eigenvectors().col(0);
	f.rms = std::sqrt(std::max(0.0, es.eigenvalues()(0)) / static_cast<double>(pts.size()));
	return f;
}

}  // namespace tagmap
