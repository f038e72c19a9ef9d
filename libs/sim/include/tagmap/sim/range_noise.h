// Range measurement error: zero-mean Gaussian along the beam, the dominant
// error of time-of-flight LiDARs at short range (datasheets quote 1-2 cm),
// plus range walk: a weak echo's pulse crosses the receiver's threshold
// later than a strong one's, so dark surfaces read slightly farther than
// bright ones (a few mm between black ink and white paper).
#pragma once

#include "tagmap/sim/rng.h"

namespace tagmap::sim
{
class RangeNoise
{
   public:
	/** `walk`: bias in metres of the weakest echo relative to a full-scale one. */
	explicit RangeNoise(double sigma, double walk = 0) : sigma_(sigma), walk_(walk) {}

	/** Measured range for a true `range` and the echo's received
	 *  `amplitude` in 0..1 (IntensityModel::amplitude). */
	double apply(double range, double amplitude, Rng& rng) const
	{
		return range + walk_ * (1.0 - amplitude) + sigma_ * gaussian(rng);
	}
	double sigma() const { return sigma_; }

   private:
	double sigma_, walk_;
};

}  // namespace tagmap::sim
