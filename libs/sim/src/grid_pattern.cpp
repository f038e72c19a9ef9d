#include <cmath>

#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
namespace
{
size_t stepsIn(double minDeg, double maxDeg, double stepDeg)
{
	return static_cast<size_t>(std::max(1.0, std::floor((maxDeg - minDeg) / stepDeg + 1e-9) + 1));
}
}  // namespace

GridPattern::GridPattern(const GridParams& p)
	: p_(p), nAz_(stepsIn(p.azMinDeg, p.azMaxDeg, p.azStepDeg)), nEl_(stepsIn(p.elMinDeg, p.elMaxDeg, p.elStepDeg))
{
	// A full turn would fire the first and last column in the same direction.
	if (p.azMaxDeg - p.azMinDeg >= 360 - 1e-9) nAz_ = static_cast<size_t>(std::round(360.0 / p.azStepDeg));
}

size_t GridPattern::rayCount(double) const { return nAz_ * nEl_; }

void GridPattern::ray(double, size_t i, Eigen::Vector3d& dir, double& dt) const
{
	dt = 0;
	const double az = p_.azMinDeg + p_.azStepDeg * static_cast<double>(i / nEl_);
	const double el = p_.elMinDeg + p_.elStepDeg * static_cast<double>(i % nEl_);
	dir = directionFromAzEl(az * M_PI / 180.0, el * M_PI / 180.0);
}

}  // namespace tagmap::sim
