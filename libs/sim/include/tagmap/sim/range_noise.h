// Range measurement error: zero-mean Gaussian along the beam, the dominant
// error of time-of-flight LiDARs at short range (datasheets quote 1-2 cm).
#pragma once

#include "tagmap/sim/rng.h"

namespace tagmap::sim
{
class RangeNoise
{
   public:
	explicit RangeNoise(double sigma) : sigma_(sigma) {}
	double apply(double range, Rng& rng) const { return range + sigma_ * gaussian(rng); }
	double sigma() const { return sigma_; }

   private:
	double sigma_;
};

}  // namespace tagmap::sim
