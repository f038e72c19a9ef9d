// Localizer (a): MRPT's own particle filter (mrpt::slam::
// CMonteCarloLocalization2D) on the tag map as a tagmap::maps::CTagMap in a
// CMultiMetricMap, from a uniform belief over the whole map. The observation
// model is CTagMap's: by default each scan's CObservationTagPoses (every seen
// tag's 6-DoF pose against the mapped tag, CTagMap_likelihood.cpp); the
// range-only CObservationBeaconRanges on request.
//
// Global localization needs a broad likelihood while the belief is spread
// (a 1-2 cm / 0.1 deg model would leave no particle of a uniform start near
// the truth) and a narrow one for tracking, so the model is annealed: tag
// poses get the belief's position and heading spread added to their standard
// deviations, in passes over the same scan that narrow with the belief
// (annealed particle filtering) until it stops narrowing; ranges get a std
// that follows the position spread between the global and tracking values. Once position and
// heading spreads are small (converged), the particle count drops to the
// tracking count. With tag poses, each scan that sees a mapped tag also
// draws a fraction of the particles where its tags alone put the robot
// (sensor resetting), gated once converged so a misread tag cannot move
// the belief.
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
enum class PfObservations
{
	tagPoses,  // CObservationTagPoses: position and heading from every tag
	ranges  // CObservationBeaconRanges only (what stock range-only filters use)
};

struct PfParams
{
	PfObservations observations = PfObservations::tagPoses;
	size_t globalParticles = 40000;  // uniform start: enough that some lie near the truth
	size_t trackingParticles = 3000;  // after the belief has converged
	double mapMargin = 3.0;  // metres around the tags' bounding box for the uniform start
	/** Tag poses: the most the belief's spread widens each tag's standard
	 *  deviations before convergence (metres, degrees). A uniform start's
	 *  spread is metres and radians; capped here, a few of 40 000 particles
	 *  still lie within one such std of the truth (the caps were chosen so
	 *  that they do on the demo site, 720 m^2). */
	double globalPoseStdPosition = 0.5;
	double globalPoseStdRotationDeg = 10;
	/** Tag poses: at most this many annealing passes per scan (each shrinks
	 *  the belief ~1/sqrt(2); 10 take a 0.5 m spread to ~1.5 cm), the
	 *  jitter between passes as a fraction of the belief's spread, and the
	 *  extra tag-pose std as a multiple of that spread: twice it while the
	 *  belief is global (a uniform start has few particles near the truth,
	 *  and a narrower likelihood collapses it onto the nearest), as wide as
	 *  it once converged: the belief is then one blob whose spread is the
	 *  motion noise, and at 2x each pass moved its mean only a fifth of the
	 *  way to the tags (spread^2 / (spread^2 + (2 spread)^2)), so the passes
	 *  stopped narrowing with the end of an odometry gap still centimetres
	 *  behind the fixes (at 1x: half the way per pass). */
	int annealPasses = 20;
	double annealJitter = 0.2;
	double annealWidth = 2;
	double trackingAnnealWidth = 1;
	double globalRangeStd = 0.4;  // ranges: metres, likelihood while the belief is spread
	double trackingRangeStd = 0.05;  // ranges: metres, once converged (>= detector range noise)
	/** Tag poses: the fraction of the particles drawn, at each scan with a
	 *  mapped tag, where its tags alone put the robot (sensor resetting, the
	 *  dual proposal of Mixture MCL), and once converged only when that pose
	 *  is within this Mahalanobis^2 of the predicted belief (3 DoF; 16.3:
	 *  chi-square 0.999). 0: off. */
	double resetFraction = 0.1;
	double resetGate = 16.3;
	double convergedSpread = 0.3;  // metres: position std (largest axis) that counts as converged
	double convergedHeadingDeg = 5;  // and heading std
	uint32_t seed = 1;
	/** Odometry noise the filter samples from (the rawlog's odometry means
	 *  are used, its stored model is not: how much to trust odometry is a
	 *  filter setting). Must cover the real odometry error per step. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel = defaultMotionModel();
	/** No odometry (`tagmap localize --no-odometry`): every step is a zero
	 *  increment, and the motion noise grows with the time since the previous
	 *  step as if the robot moved at up to this speed and turn rate (1 sigma). */
	bool noOdometry = false;
	double noOdometrySpeed = 1.0;  // m/s: a walking-pace robot
	double noOdometryTurnRateDeg = 30;  // deg/s

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
