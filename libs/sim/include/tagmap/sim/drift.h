// SLAM-like pose drift: the poses a mapping system would use to merge the
// frames. Odometry between consecutive frames is corrupted by a small random
// motion whose variance grows with the distance travelled and the time
// elapsed, so errors accumulate as a random walk (blurred, doubled surfaces
// where a place is seen again much later).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
struct DriftStep
{
	Eigen::Isometry3d truePose;
	double seconds = 0;  // time since the previous frame
	double scale = 1;  // drift multiplier (ScanRun::driftScale)
	/** The carrier's systematic odometry error (ScanRun::odometryScaleError,
	 *  odometryHeadingBiasDegPerM in radians), applied to the motion of the
	 *  carrier the sensor rides on at `mount`. */
	double scaleError = 0, headingBiasRadPerM = 0;
	Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
};

/** Drifted poses: the first equals the true one, then
 *  drifted_k = drifted_{k-1} * bias_k(true_{k-1}^-1 * true_k) * noise_k,
 *  where bias_k scales and turns the carrier's motion (identity without a
 *  systematic error). */
std::vector<Eigen::Isometry3d> driftPoses(const std::vector<DriftStep>& steps, const DriftParams& p, uint64_t seed);

}  // namespace tagmap::sim
