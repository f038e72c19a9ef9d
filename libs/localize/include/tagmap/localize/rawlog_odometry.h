// A rawlog's odometry, from either format: movement actions
// (CActionRobotMovement2D/3D) between sensory frames, or CObservationOdometry
// readings among bare observations. Read as the log is walked, so the
// localizer (odometry between scans) and `observe --window` (scans merged
// in one frame) see the same motion.
#pragma once

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace tagmap::localize
{
enum class OdometrySource
{
	none,
	actions,
	observations
};

/** Where this rawlog's odometry is: movement actions win over odometry
 *  observations (a rawlog may carry both; they are the same motion). */
OdometrySource findOdometry(const mrpt::obs::CRawlog& log);

/** The robot's pose in the odometry frame, integrated entry by entry. */
class OdometryIntegrator
{
   public:
	explicit OdometryIntegrator(OdometrySource source) : source_(source) {}

	/** Composes the movement actions' increments (if actions are the source). */
	void addActions(const mrpt::obs::CActionCollection& actions);
	/** Composes the change since the previous CObservationOdometry reading
	 *  (if readings are the source); other observations are ignored. */
	void addObservation(const mrpt::obs::CObservation& o);

	/** The pose so far (the first reading is the origin). */
	const mrpt::poses::CPose2D& pose() const { return pose_; }

   private:
	OdometrySource source_;
	std::optional<mrpt::poses::CPose2D> lastReading_;
	mrpt::poses::CPose2D pose_;
};

}  // namespace tagmap::localize
