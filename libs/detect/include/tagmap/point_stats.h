// Mean and scatter of a subset of map points, shared by the box fit
// (clustering) and the plane fit (intermediate plane).
#pragma once

#include <Eigen/Core>
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
	for (uint32_t i : pts)
	{
		const Eigen::Vector3d d = Eigen::Vector3d(xs[i], ys[i], zs[i]) - s.mean;
		s.scatter += d * d.transpose();
	}
	return s;
}

}  // namespace tagmap
