// The finite laser footprint. A real beam is a cone: where it straddles a
// black/white edge the intensity is a blend, and where it straddles a depth
// discontinuity the receiver merges the two echoes into one "mixed pixel"
// floating between the surfaces. We sample the cone with a centre ray and a
// ring of sub-rays and combine their echoes the way a pulse receiver does.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tagmap/sim/intensity_model.h"
#include "tagmap/sim/sensor_spec.h"
#include "tagmap/sim/world.h"

namespace tagmap::sim
{
struct Echo
{
	double range = 0;  // true (noise-free) range of the merged echo along the centre ray
	double strength = 0;  // footprint-averaged return strength (IntensityModel::returnStrength)
	int object = -1;  // object contributing most of the echo's energy
};

class BeamFootprint
{
   public:
	BeamFootprint(const BeamParams& p, const IntensityModel& intensity);

	/** Casts the beam along unit `d` from `o`; `up` is the sensor's up axis
	 *  (orients an elliptical footprint). False when nothing is detected. */
	bool measure(const World& world, const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& up,
				 double minRange, double maxRange, Echo& echo) const;

	/** Orthonormal basis (e1 horizontal, e2 vertical) of the cross-section of
	 *  a beam along `d` from a sensor whose up axis is `up`. */
	void crossSection(const Eigen::Vector3d& d, const Eigen::Vector3d& up, Eigen::Vector3d& e1,
					  Eigen::Vector3d& e2) const;

   private:
	BeamParams p_;
	const IntensityModel& intensity_;
	std::vector<Eigen::Vector2d> ring_;  // sub-ray offsets (tan of angle) in the beam's cross-section
};

}  // namespace tagmap::sim
