#include "tagmap/localize/localization_steps.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "tagmap/errors.h"
#include "tagmap/localize/rawlog_visit.h"

namespace tagmap::localize
{
namespace
{
class StepBuilder
{
   public:
	void addActions(const mrpt::obs::CActionCollection& actions)
	{
		for (size_t i = 0; i < actions.size(); i++)
			if (const auto* m = dynamic_cast<const mrpt::obs::CActionRobotMovement2D*>(&actions.get(i)))
			{
				// The raw reading when there is one: MRPT rebuilds poseChange
				// when it loads a rawlog, and the Thrun model does it by drawing
				// particles, so its mean differs from run to run.
				mrpt::poses::CPose2D increment = m->rawOdometryIncrementReading;
				if (m->estimationMethod != mrpt::obs::CActionRobotMovement2D::emOdometry)
					m->poseChange->getMean(increment);
				pending_ = pending_ + increment;
			}
	}

	void addObservation(const mrpt::obs::CObservation::Ptr& o)
	{
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
			s.odometry = pending_;
			steps.push_back(s);
			pending_ = mrpt::poses::CPose2D();
			ranges_.reset();
		}
	}

	std::vector<LocalizationStep> steps;

   private:
	mrpt::poses::CPose2D pending_;
	mrpt::obs::CObservationBeaconRanges::Ptr ranges_;
};
}  // namespace

std::vector<LocalizationStep> localizationSteps(const mrpt::obs::CRawlog& log, const std::string& sourceName)
{
	StepBuilder b;
	visitRawlog(log, {[&](const mrpt::obs::CActionCollection& a) { b.addActions(a); },
					  [&](const mrpt::obs::CSensoryFrame& sf) {
						  for (const auto& o : sf) b.addObservation(o);
					  },
					  [&](const mrpt::obs::CObservation::Ptr& o) { b.addObservation(o); }});
	if (b.steps.empty())
		throw InputError(sourceName, "", "no tag observations (run `tagmap observe` on the rawlog first)");
	return b.steps;
}

}  // namespace tagmap::localize
