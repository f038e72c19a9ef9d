// Pointing jitter: each pulse leaves a little off the direction the scanner's
// encoders report (mirror/prism wobble, encoder noise). The range is measured
// along the real beam but the point is placed along the reported direction,
// so surfaces thicken and ink edges blur by range x jitter, on top of the
// beam footprint.
#pragma once

#include <Eigen/Core>

#include "tagmap/sim/rng.h"

namespace tagmap::sim
{
class PointingJitter
{
   public:
	explicit PointingJitter(double sigmaMrad) : sigma_(sigmaMrad * 1e-3) {}

	/** The real beam direction for the reported unit direction `d`: turned by
	 *  a Gaussian angle of `sigma` per cross-section axis. Draws nothing when
	 *  sigma is 0, so scenes without jitter keep their random streams. */
	Eigen::Vector3d apply(const Eigen::Vector3d& d, Rng& rng) const
	{
		if (sigma_ <= 0) return d;
		const Eigen::Vector3d e1 = d.unitOrthogonal();
		const Eigen::Vector3d e2 = d.cross(e1);
		const double a = sigma_ * gaussian(rng);
		const double b = sigma_ * gaussian(rng);
		return (d + a * e1 + b * e2).normalized();
	}

   private:
	double sigma_;  // radians
};

}  // namespace tagmap::sim
