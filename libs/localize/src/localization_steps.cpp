#include "tagmap/localize/localization_steps.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <optional>

#include "tagmap/errors.h"
#include "tagmap/localize/rawlog_visit.h"

namespace tagmap::localize
{
namespace
{
enum class OdometrySource
{
	none,
	actions,
	observations
};

bool isMovement(const mrpt::obs::CAction& a)
{
	return IS_CLASS(a, mrpt::obs::CActionRobotMovement2D) || IS_CLASS(a, mrpt::obs::CActionRobotMovement3D);
}

/** Where this rawlog's odometry is: movement actions win over odometry
 *  observations (a rawlog may carry both; they are the same motion). */
OdometrySource findOdometry(const mrpt::obs::CRawlog& log)
{
	bool actions = false, observations = false;
	const auto observe = [&](const mrpt::obs::CObservation::Ptr& o) {
		observations = observations || IS_CLASS(*o, mrpt::obs::CObservationOdometry);
	};
	visitRawlog(log, {[&](const mrpt::obs::CActionCollection& a) {
						  for (size_t i = 0; i < a.size(); i++) actions = actions || isMovement(a.get(i));
					  },
					  [&](const mrpt::obs::CSensoryFrame& sf) {
						  for (const auto& o : sf) observe(o);
					  },
					  observe});
	return actions ? OdometrySource::actions : observations ? OdometrySource::observations : OdometrySource::none;
}

/** The ground-plane increment of a movement action. The raw reading when
 *  there is one: MRPT rebuilds poseChange when it loads a rawlog, and the
 *  Thrun (2D) and 6-DoF particle (3D) models do it by drawing samples, so
 *  their mean differs from run to run. A 3D action whose raw reading is
 *  zero while its mean is not (written without one) gives its mean. */
mrpt::poses::CPose2D movementIncrement(const mrpt::obs::CAction& a)
{
	using mrpt::obs::CActionRobotMovement2D;
	using mrpt::obs::CActionRobotMovement3D;
	if (const auto* m = dynamic_cast<const CActionRobotMovement2D*>(&a))
	{
		mrpt::poses::CPose2D increment = m->rawOdometryIncrementReading;
		if (m->estimationMethod != CActionRobotMovement2D::emOdometry) m->poseChange->getMean(increment);
		return increment;
	}
	const auto& m = dynamic_cast<const CActionRobotMovement3D&>(a);
	const bool haveRaw = m.estimationMethod == CActionRobotMovement3D::emOdometry &&
						 m.rawOdometryIncrementReading != mrpt::poses::CPose3D();
	return mrpt::poses::CPose2D(haveRaw ? m.rawOdometryIncrementReading : m.poseChange.mean);
}

class StepBuilder
{
   public:
	explicit StepBuilder(OdometrySource source) : source_(source) {}

	void addActions(const mrpt::obs::CActionCollection& actions)
	{
		if (source_ != OdometrySource::actions) return;
		for (size_t i = 0; i < actions.size(); i++)
			if (isMovement(actions.get(i))) pending_ = pending_ + movementIncrement(actions.get(i));
	}

	void addObservation(const mrpt::obs::CObservation::Ptr& o)
	{
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o);
			odo && source_ == OdometrySource::observations)
		{
			// Absolute readings: the motion is the change since the last one.
			if (lastReading_) pending_ = pending_ + (odo->odometry - *lastReading_);
			lastReading_ = odo->odometry;
		}
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
	OdometrySource source_;
	std::optional<mrpt::poses::CPose2D> lastReading_;
	mrpt::poses::CPose2D pending_;
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
