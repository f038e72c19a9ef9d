// What a LiDAR reports as intensity: the echo strength of a diffuse surface
// (reflectivity x cos(incidence)^k), a residual range falloff left after the
// sensor's own calibration, additive noise, clipped at the receiver's
// saturation level (full scale), quantized to the sensor's native bit depth
// (8 or 16 bits: integer levels, not a continuum). The output
// scale (0..1, 0..255, 0..65535) is applied only when writing points, so
// changing it never changes a ray or a noise draw.
#pragma once

#include <algorithm>
#include <cmath>

#include "tagmap/sim/rng.h"
#include "tagmap/sim/sensor_spec.h"

namespace tagmap::sim
{
class IntensityModel
{
   public:
	explicit IntensityModel(const IntensityParams& p) : p_(p) {}

	/** Relative echo strength of one sub-ray on a surface, before range effects. */
	double returnStrength(double reflectivity, double cosIncidence) const
	{
		return reflectivity * std::pow(std::max(0.0, cosIncidence), p_.incidenceExponent);
	}

	/** True if an echo of this strength at this range is detected at all. */
	bool detected(double strength, double range) const
	{
		if (p_.detectionRange10 > 0)
		{
			constexpr double kSpecReflectivity = 0.1;  // the 10 % of detectionRange10
			const double r = p_.detectionRange10 / std::max(range, p_.rangeReference);
			return strength * r * r >= kSpecReflectivity;
		}
		return strength * falloff(range) >= p_.detectionThreshold;
	}

	/** Noise-free received level in 0..1 of full scale (saturated echoes
	 *  are 1): what the range walk depends on. */
	double amplitude(double strength, double range) const
	{
		return std::clamp(p_.gain * strength * falloff(range) / p_.saturation, 0.0, 1.0);
	}

	/** Reported intensity in 0..1. `strength` is the footprint-averaged
	 *  returnStrength() of the echo (missed sub-rays count as zero). */
	double intensity(double strength, double range, Rng& rng) const
	{
		const double v = p_.gain * strength * falloff(range) + p_.noiseSigma * gaussian(rng);
		const double clipped = std::clamp(v / p_.saturation, 0.0, 1.0);
		if (p_.bits <= 0) return clipped;
		const double levels = static_cast<double>((1u << p_.bits) - 1u);
		return std::round(clipped * levels) / levels;
	}

   private:
	double falloff(double range) const
	{
		return std::pow(p_.rangeReference / std::max(range, p_.rangeReference), p_.rangeFalloffExponent);
	}
	IntensityParams p_;
};

}  // namespace tagmap::sim
