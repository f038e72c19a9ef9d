// Localizer (a): MRPT's own particle filter (mrpt::slam::
// CMonteCarloLocalization2D) on the tag map as range-only beacons
// (CLandmarksMap, one featBeacon per tag) with the CObservationBeaconRanges
// of `tagmap observe`, from a uniform belief over the whole map.
//
// Range-only global localization needs a broad likelihood while the belief
// is spread (a 1-2 cm range std would leave almost no particle near the
// truth) and a narrow one for tracking, so the range std is annealed: it
// follows the particles' position spread between the global and tracking
// values. Once position and heading spreads are small (converged), the
// particle count drops to the tracking count.
#pragma once

#include <mrpt/obs/CActionRobotMovement2D.h>

#include <cstdint>
#include <vector>

#include "tagmap/count_progress.h"
#include "tagmap/localize/localization_steps.h"
#include "tagmap/localize/trajectory_tum.h"
#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
struct PfParams
{
	size_t globalParticles = 40000;  // uniform start: enough that some lie near the truth
	size_t trackingParticles = 3000;  // after the belief has converged
	double mapMargin = 3.0;  // metres around the tags' bounding box for the uniform start
	double globalRangeStd = 0.4;  // metres, likelihood while the belief is spread
	double trackingRangeStd = 0.05;  // metres, once converged (>= detector range noise)
	double convergedSpread = 0.3;  // metres: position std (largest axis) that counts as converged
	double convergedHeadingDeg = 5;  // and heading std
	uint32_t seed = 1;
	/** Odometry noise the filter samples from (the rawlog's odometry means
	 *  are used, its stored model is not: how much to trust odometry is a
	 *  filter setting). Must cover the real odometry error per step. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel = defaultMotionModel();

	static mrpt::obs::CActionRobotMovement2D::TMotionModelOptions defaultMotionModel();
};

struct PfResult
{
	Trajectory trajectory;  // sensor poses: particle mean (+) the LiDAR's pose on the robot
	std::vector<double> spread;  // per step, metres
	long convergedAtStep = -1;  // the filter's own verdict (no ground truth involved)
};

/** `progress`: steps done and in all, after each filter update. */
PfResult runParticleFilter(const std::vector<TagDetection>& mapTags, const std::vector<LocalizationStep>& steps,
						   const PfParams& params = {}, const CountProgressFn& progress = {});

}  // namespace tagmap::localize
