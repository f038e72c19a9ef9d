#include "tagmap/localize/beacon_ranges.h"

#include <algorithm>
#include <cmath>

#include "tagmap/mrpt/beacon_id.h"

namespace tagmap::localize
{
mrpt::obs::CObservationBeaconRanges::Ptr makeBeaconRanges(const std::vector<TagDetection>& tags,
														   const mrpt::poses::CPose3D& sensorPose,
														   const BeaconRangeParams& params)
{
	auto obs = mrpt::obs::CObservationBeaconRanges::Create();
	obs->minSensorDistance = 0;
	obs->maxSensorDistance = static_cast<float>(params.maxRange);
	double stdError = params.minStd;
	for (const TagDetection& t : tags)
	{
		mrpt::obs::CObservationBeaconRanges::TMeasurement m;
		try
		{
			m.beaconID = static_cast<int32_t>(mrpt_bridge::encodeBeaconId(t.family, t.id));
		}
		catch (const std::invalid_argument&)
		{
			continue;
		}
		const Eigen::Vector3d p = t.position();
		m.sensedDistance = static_cast<float>(p.norm());
		m.sensorLocationOnRobot = mrpt::poses::CPoint3D(sensorPose.x(), sensorPose.y(), sensorPose.z());
		obs->sensedData.push_back(m);
		if (p.norm() > 0)
		{
			const Eigen::Vector3d u = p.normalized();
			const double var = u.dot(t.covariance.topLeftCorner<3, 3>() * u);
			if (std::isfinite(var) && var > 0) stdError = std::max(stdError, std::sqrt(var));
		}
	}
	obs->stdError = static_cast<float>(stdError);
	return obs;
}

}  // namespace tagmap::localize
