// CTagMap's range-only likelihood peaks at the true pose, and agrees with
// CLandmarksMap built from the same tags (the model it mirrors). Its tag-pose
// likelihood peaks at the true pose in position and heading, honours the
// sensor's mounting pose, and a wrong or unknown tag costs every pose at most
// the outlier term.
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationBeaconRanges.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/landmarks_map.h"
#include "tagmap/obs/CObservationTagPoses.h"

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

TEST(MrptLikelihood, RangesLeftToTheLandmarksMapWhenNotScored)
{
	// The --ini's tagMap (scoreBeaconRanges=false): ranges give log(1)
	// everywhere, so a CMultiMetricMap with the landmarksMap counts them once.
	const auto tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	m.setTags(tags);
	m.likelihoodOptions.scoreBeaconRanges = false;
	const auto obs = rangesFrom(mrpt::poses::CPose3D(1, 0, 0, 0, 0, 0), tags);
	EXPECT_EQ(m.computeObservationLikelihood(obs, mrpt::poses::CPose3D(1.4, -0.3, 0, 0.1, 0, 0)), 0.0);
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

namespace
{
Eigen::Isometry3d isometry(const mrpt::poses::CPose3D& p)
{
	return Eigen::Isometry3d(p.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen());
}

/** What a sensor mounted at `sensorOnRobot` on a robot at `robot` sees of
 *  the tags, exactly, with a 3 mm / 0.3 deg covariance. */
obs::CObservationTagPoses tagPosesFrom(const mrpt::poses::CPose3D& robot, const mrpt::poses::CPose3D& sensorOnRobot,
									   const std::vector<TagDetection>& tags)
{
	obs::CObservationTagPoses o;
	o.sensorPose = sensorOnRobot;
	const Eigen::Isometry3d T_G_sensor = isometry(robot + sensorOnRobot);
	for (TagDetection t : tags)
	{
		t.pose = T_G_sensor.inverse() * t.pose;
		t.covariance.setZero();
		t.covariance.diagonal() << Eigen::Vector3d::Constant(0.003 * 0.003),
			Eigen::Vector3d::Constant(std::pow(0.3 * M_PI / 180, 2));
		o.tags.push_back(t);
	}
	return o;
}

class MrptTagPosesLikelihood : public ::testing::Test
{
   protected:
	void SetUp() override { m.setTags(tags); }
	const std::vector<TagDetection> tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	const mrpt::poses::CPose3D truth{1.0, 0.2, 0, 0.3, 0, 0};
};
}  // namespace

TEST_F(MrptTagPosesLikelihood, PeaksAtTruePoseAndHeading)
{
	// A LiDAR 0.3 m ahead, 1.2 m up and turned: predictions must use it.
	const mrpt::poses::CPose3D mount(0.3, 0, 1.2, 0.2, 0, 0);
	const auto obs = tagPosesFrom(truth, mount, tags);
	ASSERT_TRUE(m.canComputeObservationLikelihood(obs));

	const double atTruth = m.computeObservationLikelihood(obs, truth);
	EXPECT_NEAR(atTruth, 0.0, 1e-4);  // log(1 + exp(-k^2/2)) per tag
	for (double dx : {-0.02, 0.0, 0.02})
		for (double dyawDeg : {-0.5, 0.0, 0.5})
		{
			if (dx == 0 && dyawDeg == 0) continue;
			const mrpt::poses::CPose3D p(truth.x() + dx, truth.y(), 0, truth.yaw() + dyawDeg * M_PI / 180, 0, 0);
			EXPECT_LT(m.computeObservationLikelihood(obs, p), atTruth - 1) << dx << " " << dyawDeg;
		}
	// Without the mounting pose the same tags fit elsewhere: not at the truth.
	auto unmounted = obs;
	unmounted.sensorPose = mrpt::poses::CPose3D();
	EXPECT_LT(m.computeObservationLikelihood(unmounted, truth), atTruth - 10);
}

TEST_F(MrptTagPosesLikelihood, OutlierCostsAtMostTheOutlierTerm)
{
	const double k = m.likelihoodOptions.tagPoseOutlierSigmas;
	auto obs = tagPosesFrom(truth, mrpt::poses::CPose3D(), tags);
	obs.tags[0].pose.translation() += Eigen::Vector3d(0, 1.5, 0);  // a wrong association, 1.5 m off
	TagDetection unknown = obs.tags[1];
	unknown.id = 999;
	obs.tags.push_back(unknown);
	// Each bad tag costs about k^2/2 (log(exp(-d^2/2) + exp(-k^2/2))), not -inf.
	const double atTruth = m.computeObservationLikelihood(obs, truth);
	EXPECT_NEAR(atTruth, -k * k, 1e-4);
	// The truth still beats a pose that fits the wrong tag better.
	const mrpt::poses::CPose3D shifted(truth.x(), truth.y() - 1.5, 0, truth.yaw(), 0, 0);
	EXPECT_LT(m.computeObservationLikelihood(obs, shifted), atTruth);
	// Annealing: a wider model scores a near miss better.
	const mrpt::poses::CPose3D nearMiss(truth.x() + 0.1, truth.y(), 0, truth.yaw(), 0, 0);
	const double sharp = m.computeObservationLikelihood(obs, nearMiss);
	m.likelihoodOptions.tagPoseExtraStdPosition = 0.2;
	EXPECT_GT(m.computeObservationLikelihood(obs, nearMiss), sharp);
}
