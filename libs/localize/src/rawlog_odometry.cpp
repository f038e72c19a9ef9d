#include "tagmap/localize/rawlog_odometry.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "tagmap/localize/rawlog_visit.h"

namespace tagmap::localize
{
namespace
{
bool isMovement(const mrpt::obs::CAction& a)
{
	return IS_CLASS(a, mrpt::obs::CActionRobotMovement2D) || IS_CLASS(a, mrpt::obs::CActionRobotMovement3D);
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

}  // namespace

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

void OdometryIntegrator::addActions(const mrpt::obs::CActionCollection& actions)
{
	if (source_ != OdometrySource::actions) return;
	for (size_t i = 0; i < actions.size(); i++)
		if (isMovement(actions.get(i))) pose_ = pose_ + movementIncrement(actions.get(i));
}

void OdometryIntegrator::addObservation(const mrpt::obs::CObservation& o)
{
	const auto* odo = dynamic_cast<const mrpt::obs::CObservationOdometry*>(&o);
	if (!odo || source_ != OdometrySource::observations) return;
	// Absolute readings: the motion is the change since the last one.
	if (lastReading_) pose_ = pose_ + (odo->odometry - *lastReading_);
	lastReading_ = odo->odometry;
}

}  // namespace tagmap::localize
