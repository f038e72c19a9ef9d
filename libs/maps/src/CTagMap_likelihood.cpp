// Range-only likelihood of CObservationBeaconRanges against the tag centres,
// the model CLandmarksMap and CBeaconMap use: a Gaussian on each range to a
// known beacon, a uniform over the sensor range for unknown beacons. This is
// what lets pf-localization/ro-localization style filters localize on tags.
#include <mrpt/obs/CObservationBeaconRanges.h>

#include <cmath>

#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/beacon_id.h"

namespace tagmap::maps
{
bool CTagMap::internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const
{
	return IS_CLASS(obs, mrpt::obs::CObservationBeaconRanges);
}

double CTagMap::internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
													  const mrpt::poses::CPose3D& robotPose) const
{
	const auto* o = dynamic_cast<const mrpt::obs::CObservationBeaconRanges*>(&obs);
	if (!o) return 0;  // log(1): no information

	const double sensorStd = likelihoodOptions.beaconRangesUseObservationStd ? o->stdError
																			 : likelihoodOptions.beaconRangesStd;
	ASSERT_GT_(sensorStd, 0.0);
	const bool haveRange = o->maxSensorDistance > o->minSensorDistance;
	const double logUniform = haveRange ? -std::log(o->maxSensorDistance - o->minSensorDistance) : 0;

	double logLik = 0;
	for (const auto& meas : o->sensedData)
	{
		if (std::isnan(meas.sensedDistance)) continue;
		const mrpt::poses::CPoint3D sensor = robotPose + meas.sensorLocationOnRobot;
		const TagDetection* tag = nullptr;
		for (const auto& t : tags())
			if (mrpt_bridge::encodeBeaconId(t.family, t.id) == static_cast<int64_t>(meas.beaconID)) tag = &t;
		if (!tag)
		{
			logLik += logUniform;
			continue;
		}
		const Eigen::Vector3d c = tag->position();
		const double expected = sensor.distanceTo(mrpt::math::TPoint3D(c.x(), c.y(), c.z()));
		const double sensed = std::max(0.0, static_cast<double>(meas.sensedDistance));
		logLik += -0.5 * std::pow((expected - sensed) / sensorStd, 2);
	}
	return logLik;
}

}  // namespace tagmap::maps
