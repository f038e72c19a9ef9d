// Where a sensor fires: ray directions in the sensor frame (x forward,
// y left, z up) as a function of time. Patterns are pure functions of the
// ray index, so any block of rays can be generated independently (threads).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <memory>

#include "tagmap/sim/sensor_spec.h"

namespace tagmap::sim
{
class ScanPattern
{
   public:
	virtual ~ScanPattern() = default;
	/** Rays fired in a frame of `duration` seconds (Grid: one full sweep). */
	virtual size_t rayCount(double duration) const = 0;
	/** Ray `i` of a frame starting at absolute time `t0`: unit direction and
	 *  its time offset after t0 (for motion during the frame). */
	virtual void ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const = 0;
};

/** Livox MID-40-like rosette from two counter-rotating Risley prisms. */
class RosettePattern : public ScanPattern
{
   public:
	explicit RosettePattern(const RosetteParams& p);
	size_t rayCount(double duration) const override;
	void ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const override;

   private:
	RosetteParams p_;
	double w1_, w2_, amp_;  // rad/s, rad/s, deflection of each prism (rad)
};

/** Ouster/Velodyne-like: all beams fire together at each of `columns`
 *  azimuths per revolution. */
class SpinningPattern : public ScanPattern
{
   public:
	explicit SpinningPattern(const SpinningParams& p);
	size_t rayCount(double duration) const override;
	void ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const override;

   private:
	SpinningParams p_;
};

/** Terrestrial scanner: a dense regular azimuth/elevation grid. Timing is
 *  irrelevant for a static station, so dt is 0. */
class GridPattern : public ScanPattern
{
   public:
	explicit GridPattern(const GridParams& p);
	size_t rayCount(double duration) const override;
	void ray(double t0, size_t i, Eigen::Vector3d& dir, double& dt) const override;

   private:
	GridParams p_;
	size_t nAz_, nEl_;
};

std::unique_ptr<ScanPattern> makeScanPattern(const SensorSpec& spec);

/** Unit direction from azimuth (about z, from +x towards +y) and elevation. */
inline Eigen::Vector3d directionFromAzEl(double az, double el)
{
	return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

}  // namespace tagmap::sim
