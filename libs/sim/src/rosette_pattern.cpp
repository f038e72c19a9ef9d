#include <cmath>

#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
RosettePattern::RosettePattern(const RosetteParams& p) : p_(p)
{
	constexpr double kRpmToRadS = 2 * M_PI / 60.0;
	w1_ = p.prism1Rpm * kRpmToRadS;
	w2_ = p.prism2Rpm * kRpmToRadS;
	// Each prism deflects by the same angle; aligned they reach the FOV edge,
	// opposed they cancel, which sends every petal through the centre.
	amp_ = 0.25 * p.fovDeg * M_PI / 180.0;
}

size_t RosettePattern::rayCount(double duration) const
{
	return static_cast<size_t>(std::llround(std::max(0.0, duration) * p_.pointsPerSecond));
}

void RosettePattern::ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const
{
	dt = static_cast<double>(i) / p_.pointsPerSecond;
	const double t = t0 + dt;
	// First-order Risley model: the two deflections add as 2D vectors.
	const double dy = amp_ * (std::cos(w1_ * t) + std::cos(w2_ * t));
	const double dz = amp_ * (std::sin(w1_ * t) + std::sin(w2_ * t));
	const double theta = std::hypot(dy, dz);  // off-axis angle
	if (theta < 1e-12)
	{
		dir = Eigen::Vector3d::UnitX();
		return;
	}
	const double s = std::sin(theta) / theta;
	dir = Eigen::Vector3d(std::cos(theta), s * dy, s * dz);
}

}  // namespace tagmap::sim
