#include "tagmap/localize/localization_steps.h"

#include <mrpt/obs/CSensoryFrame.h>

#include "tagmap/errors.h"
#include "tagmap/localize/rawlog_odometry.h"
#include "tagmap/localize/rawlog_visit.h"

namespace tagmap::localize
{
namespace
{
class StepBuilder
{
   public:
	explicit StepBuilder(OdometrySource source) : odometry_(source) {}

	void addActions(const mrpt::obs::CActionCollection& actions) { odometry_.addActions(actions); }

	void addObservation(const mrpt::obs::CObservation::Ptr& o)
	{
		odometry_.addObservation(*o);
		if (auto b = std::dynamic_pointer_cast<mrpt::obs::CObservationBeaconRanges>(o)) ranges_ = b;
		if (auto t = std::dynamic_pointer_cast<obs::CObservationTagPoses>(o))
		{
			LocalizationStep s;
			s.stamp = mrpt::Clock::toDouble(t->timestamp);
			s.tags = t;
			s.sensorPose = t->sensorPose;
			// The ranges written with these tags (same stamp), else none.
			s.ranges = ranges_ && ranges_->timestamp == t->timestamp ? ranges_
																	   : mrpt::obs::CObservationBeaconRanges::Create();
			// The motion since the previous step.
			s.odometry = odometry_.pose() - lastStepPose_;
			steps.push_back(s);
			lastStepPose_ = odometry_.pose();
			ranges_.reset();
		}
	}

	std::vector<LocalizationStep> steps;

   private:
	OdometryIntegrator odometry_;
	mrpt::poses::CPose2D lastStepPose_;
	mrpt::obs::CObservationBeaconRanges::Ptr ranges_;
};
}  // namespace

std::vector<LocalizationStep> localizationSteps(const mrpt::obs::CRawlog& log, const std::string& sourceName,
												OdometryUse odometry)
{
	const OdometrySource source = odometry == OdometryUse::ignored ? OdometrySource::none : findOdometry(log);
	StepBuilder b(source);
	visitRawlog(log, {[&](const mrpt::obs::CActionCollection& a) { b.addActions(a); },
					  [&](const mrpt::obs::CSensoryFrame& sf) {
						  for (const auto& o : sf) b.addObservation(o);
					  },
					  [&](const mrpt::obs::CObservation::Ptr& o) { b.addObservation(o); }});
	if (b.steps.empty())
		throw InputError(sourceName, "", "no tag observations (run `tagmap observe` on the rawlog first)");
	if (odometry == OdometryUse::required && source == OdometrySource::none)
		throw InputError(sourceName, "",
						 "no odometry (no CActionRobotMovement2D/3D action and no CObservationOdometry); "
						 "the particle filter needs it, or localize with --no-odometry");
	return b.steps;
}

}  // namespace tagmap::localize
