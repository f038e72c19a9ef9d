// Scoring an estimated trajectory against ground truth: poses are paired by
// time stamp; "converged" is the first step from which the translation and
// rotation errors stay below thresholds to the end, and the RMSEs are taken from
// there on (a global localizer is not expected to know where it is before
// it has seen enough; how long that takes is converged_at_step).
#pragma once

#include <string>

#include "tagmap/localize/trajectory_tum.h"

namespace tagmap::localize
{
struct TrajectoryErrorParams
{
	double stampTolerance = 1e-3;  // seconds; estimates without a truth this close are ignored
	double convergedTranslation = 0.3;  // metres
	double convergedRotationDeg = 10;  // a right position with a wrong heading is not converged
};

struct TrajectoryErrors
{
	size_t estimated = 0;  // poses in the estimate
	size_t matched = 0;  // of them, paired with a true pose
	long convergedAtStep = -1;  // index into the matched estimates; -1: never
	double convergedAtSeconds = -1;  // since the first matched estimate
	// From convergedAtStep on (all NaN if never converged):
	double rmseTranslation = 0;  // metres
	double rmseRotationDeg = 0;  // angle of R_true^T R_est
	double maxTranslation = 0;
	// Over every matched pose, converged or not:
	double rmseTranslationAll = 0;
};

TrajectoryErrors evaluateTrajectory(const Trajectory& estimate, const Trajectory& truth,
									const TrajectoryErrorParams& params = {});

/** {"rmse_translation_m": ..., "rmse_rotation_deg": ..., "converged_at_step": ..., ...}
 *  plus `extraFields` (e.g. "\"method\": \"pf\""), one JSON object. */
std::string errorsToJson(const TrajectoryErrors& e, const std::string& extraFields = {});

}  // namespace tagmap::localize
