#include <cmath>

#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
SpinningPattern::SpinningPattern(const SpinningParams& p) : p_(p) {}

size_t SpinningPattern::rayCount(double duration) const
{
	const double columns = std::round(std::max(0.0, duration) * p_.revPerSecond * p_.columns);
	return static_cast<size_t>(columns) * p_.beamElevationsDeg.size();
}

void SpinningPattern::ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const
{
	const size_t beams = p_.beamElevationsDeg.size();
	const size_t column = i / beams;
	const double colRate = p_.revPerSecond * p_.columns;  // columns per second
	dt = static_cast<double>(column) / colRate;
	// Absolute azimuth from absolute time, so consecutive frames continue the spin.
	const double revs = (t0 + dt) * p_.revPerSecond;
	const double az = 2 * M_PI * (revs - std::floor(revs));
	dir = directionFromAzEl(az, p_.beamElevationsDeg[i % beams] * M_PI / 180.0);
}

}  // namespace tagmap::sim
