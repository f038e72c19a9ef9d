// CTagMap's range-only likelihood peaks at the true pose, and agrees with
// CLandmarksMap built from the same tags (the model it mirrors).
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationBeaconRanges.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/landmarks_map.h"

using namespace tagmap;

namespace
{
mrpt::obs::CObservationBeaconRanges rangesFrom(const mrpt::poses::CPose3D& pose, const std::vector<TagDetection>& tags)
{
	mrpt::obs::CObservationBeaconRanges obs;
	obs.minSensorDistance = 0;
	obs.maxSensorDistance = 30;
	for (const auto& t : tags)
	{
		mrpt::obs::CObservationBeaconRanges::TMeasurement m;
		m.beaconID = static_cast<int32_t>(mrpt_bridge::encodeBeaconId(t.family, t.id));
		const Eigen::Vector3d c = t.position();
		m.sensedDistance = static_cast<float>(pose.distanceTo(mrpt::poses::CPoint3D(c.x(), c.y(), c.z())));
		obs.sensedData.push_back(m);
	}
	return obs;
}
}  // namespace

TEST(MrptLikelihood, PeaksAtTruePose)
{
	const auto tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	m.setTags(tags);
	const mrpt::poses::CPose3D truth(1.0, 0.2, 0, 0.3, 0, 0);
	const auto obs = rangesFrom(truth, tags);
	ASSERT_TRUE(m.canComputeObservationLikelihood(obs));

	const double atTruth = m.computeObservationLikelihood(obs, truth);
	EXPECT_NEAR(atTruth, 0.0, 1e-6);
	for (double dx : {-0.3, -0.1, 0.1, 0.3})
		for (double dy : {-0.3, 0.0, 0.3})
		{
			const mrpt::poses::CPose3D p(truth.x() + dx, truth.y() + dy, 0, 0.3, 0, 0);
			EXPECT_LT(m.computeObservationLikelihood(obs, p), atTruth) << dx << " " << dy;
		}
}

TEST(MrptLikelihood, MatchesCLandmarksMap)
{
	const auto tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	m.setTags(tags);
	const auto lm = mrpt_bridge::tagsToLandmarksMap(tags);
	const auto obs = rangesFrom(mrpt::poses::CPose3D(1, 0, 0, 0, 0, 0), tags);
	const mrpt::poses::CPose3D probe(1.4, -0.3, 0, 0.1, 0, 0);
	EXPECT_NEAR(m.computeObservationLikelihood(obs, probe), lm.computeObservationLikelihood(obs, probe), 1e-3);
}

TEST(MrptLikelihood, UnknownBeaconIsUniform)
{
	maps::CTagMap m;
	m.setTags(mrpt_test::syntheticTags());
	mrpt::obs::CObservationBeaconRanges obs;
	obs.minSensorDistance = 0;
	obs.maxSensorDistance = 20;
	mrpt::obs::CObservationBeaconRanges::TMeasurement meas;
	meas.beaconID = 42;
	meas.sensedDistance = 3;
	obs.sensedData.push_back(meas);
	EXPECT_NEAR(m.computeObservationLikelihood(obs, mrpt::poses::CPose3D()), -std::log(20.0), 1e-6);
}
