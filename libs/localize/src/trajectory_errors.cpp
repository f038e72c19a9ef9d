#include "tagmap/localize/trajectory_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace tagmap::localize
{
namespace
{
/** The true pose with the nearest stamp, or nullptr if none is within tolerance. */
const StampedPose* nearest(const Trajectory& truth, double stamp, double tolerance)
{
	const auto it = std::lower_bound(truth.begin(), truth.end(), stamp,
									 [](const StampedPose& p, double t) { return p.stamp < t; });
	const StampedPose* best = nullptr;
	for (auto c : {it, it == truth.begin() ? it : std::prev(it)})
		if (c != truth.end() && std::abs(c->stamp - stamp) <= tolerance &&
			(!best || std::abs(c->stamp - stamp) < std::abs(best->stamp - stamp)))
			best = &*c;
	return best;
}

std::string number(double v)
{
	if (!std::isfinite(v)) return "null";
	std::ostringstream s;
	s.precision(6);
	s << v;
	return s.str();
}
}  // namespace

TrajectoryErrors evaluateTrajectory(const Trajectory& estimate, const Trajectory& truthIn,
									const TrajectoryErrorParams& params)
{
	Trajectory truth = truthIn;
	std::sort(truth.begin(), truth.end(), [](const auto& a, const auto& b) { return a.stamp < b.stamp; });

	struct Pair
	{
		double stamp, translation, rotationDeg;
	};
	std::vector<Pair> pairs;
	for (const StampedPose& e : estimate)
		if (const StampedPose* t = nearest(truth, e.stamp, params.stampTolerance))
		{
			const Eigen::AngleAxisd dR(t->pose.linear().transpose() * e.pose.linear());
			pairs.push_back({e.stamp, (e.pose.translation() - t->pose.translation()).norm(), dR.angle() * 180 / M_PI});
		}

	TrajectoryErrors r;
	r.estimated = estimate.size();
	r.matched = pairs.size();
	const double nan = std::numeric_limits<double>::quiet_NaN();
	r.rmseTranslation = r.rmseRotationDeg = r.maxTranslation = r.rmseTranslationAll = nan;
	if (pairs.empty()) return r;

	double all = 0;
	for (const Pair& p : pairs) all += p.translation * p.translation;
	r.rmseTranslationAll = std::sqrt(all / pairs.size());

	// Walk back from the end while the error stays small.
	size_t k = pairs.size();
	while (k > 0 && pairs[k - 1].translation <= params.convergedTranslation &&
		   pairs[k - 1].rotationDeg <= params.convergedRotationDeg)
		k--;
	if (k == pairs.size()) return r;
	r.convergedAtStep = static_cast<long>(k);
	r.convergedAtSeconds = pairs[k].stamp - pairs.front().stamp;
	double st = 0, sr = 0, mx = 0;
	for (size_t i = k; i < pairs.size(); i++)
	{
		st += pairs[i].translation * pairs[i].translation;
		sr += pairs[i].rotationDeg * pairs[i].rotationDeg;
		mx = std::max(mx, pairs[i].translation);
	}
	const double n = static_cast<double>(pairs.size() - k);
	r.rmseTranslation = std::sqrt(st / n);
	r.rmseRotationDeg = std::sqrt(sr / n);
	r.maxTranslation = mx;
	return r;
}

std::string errorsToJson(const TrajectoryErrors& e, const std::string& extraFields)
{
	std::ostringstream j;
	j << "{\n  \"rmse_translation_m\": " << number(e.rmseTranslation) << ",\n  \"rmse_rotation_deg\": "
	  << number(e.rmseRotationDeg) << ",\n  \"converged_at_step\": " << e.convergedAtStep
	  << ",\n  \"converged_at_s\": " << number(e.convergedAtSeconds)
	  << ",\n  \"max_translation_m\": " << number(e.maxTranslation)
	  << ",\n  \"rmse_translation_all_m\": " << number(e.rmseTranslationAll) << ",\n  \"estimated\": " << e.estimated
	  << ",\n  \"matched\": " << e.matched;
	if (!extraFields.empty()) j << ",\n  " << extraFields;
	j << "\n}\n";
	return j.str();
}

}  // namespace tagmap::localize
