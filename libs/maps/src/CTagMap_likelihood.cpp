// Observation likelihoods against the mapped tags.
//
// CObservationBeaconRanges: range-only against the tag centres, the model
// CLandmarksMap and CBeaconMap use: a Gaussian on each range to a known
// beacon, a uniform over the sensor range for unknown beacons. This is what
// lets pf-localization/ro-localization style filters localize on tags.
//
// CObservationTagPoses: each seen tag's whole pose T_sensor_tag against its
// prediction T_G_sensor^-1 T_G_tag (T_G_sensor = robot pose (+) the
// observation's sensorPose): a Gaussian on the 6-DoF residual (the seen tag's
// covariance, floored, plus the map tag's) mixed with an outlier term as
// likely as a residual `tagPoseOutlierSigmas` away. A range says nothing
// about heading; a tag's orientation fixes it to tenths of a degree in one
// scan. The Gaussian's normalisation is left out: it is the same for every
// robot pose (up to the map tag's covariance turning with the heading), and
// a particle filter only compares poses.
#include <mrpt/obs/CObservationBeaconRanges.h>

#include <cmath>

#include "tagmap/maps/CTagMap.h"
#include "tagmap/maps/tag_pose_model.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/obs/CObservationTagPoses.h"

namespace tagmap::maps
{
bool CTagMap::internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const
{
	return IS_CLASS(obs, mrpt::obs::CObservationBeaconRanges) || IS_CLASS(obs, tagmap::obs::CObservationTagPoses);
}

namespace
{
TagPoseNoise tagPoseNoise(const TTagLikelihoodOptions& o)
{
	TagPoseNoise n;
	n.minSeenStdPosition = o.tagPoseMinStdPosition;
	n.minSeenStdRotationDeg = o.tagPoseMinStdRotationDeg;
	n.mapTagStdPosition = o.mapTagStdPosition;
	n.mapTagStdRotationDeg = o.mapTagStdRotationDeg;
	n.extraStdPosition = o.tagPoseExtraStdPosition;
	n.extraStdRotationDeg = o.tagPoseExtraStdRotationDeg;
	return n;
}
}  // namespace

const std::vector<int64_t>& CTagMap::beaconIds() const
{
	const auto& ts = tags();
	if (m_beaconIds.size() != ts.size())
	{
		m_beaconIds.clear();
		for (const auto& t : ts) m_beaconIds.push_back(mrpt_bridge::encodeBeaconId(t.family, t.id));
	}
	return m_beaconIds;
}

double CTagMap::tagPosesLogLikelihood(const obs::CObservationTagPoses& o, const mrpt::poses::CPose3D& robotPose) const
{
	const TagPoseNoise noise = tagPoseNoise(likelihoodOptions);
	// log(exp(-d^2/2) + exp(-k^2/2)), computed without underflow.
	const double logOutlier = -0.5 * std::pow(likelihoodOptions.tagPoseOutlierSigmas, 2);
	const Eigen::Isometry3d T_G_sensor(
		(robotPose + o.sensorPose).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen());
	double logLik = 0;
	for (const TagDetection& seen : o.tags)
	{
		const TagDetection* mapTag = nullptr;
		for (const auto& t : tags())
			if (t.family == seen.family && t.id == seen.id) mapTag = &t;
		if (!mapTag)
		{
			logLik += logOutlier;  // an unknown tag is an outlier whatever the pose
			continue;
		}
		const double logInlier = -0.5 * tagPoseResidual(T_G_sensor, *mapTag, seen, noise).mahalanobis2();
		const double hi = std::max(logInlier, logOutlier), lo = std::min(logInlier, logOutlier);
		logLik += hi + std::log1p(std::exp(lo - hi));
	}
	return logLik;
}

double CTagMap::internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
													  const mrpt::poses::CPose3D& robotPose) const
{
	if (const auto* poses = dynamic_cast<const tagmap::obs::CObservationTagPoses*>(&obs))
		return tagPosesLogLikelihood(*poses, robotPose);
	const auto* o = dynamic_cast<const mrpt::obs::CObservationBeaconRanges*>(&obs);
	if (!o || !likelihoodOptions.scoreBeaconRanges) return 0;  // log(1): no information

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
		const std::vector<int64_t>& ids = beaconIds();
		for (size_t i = 0; i < ids.size(); i++)
			if (ids[i] == static_cast<int64_t>(meas.beaconID)) tag = &tags()[i];
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
