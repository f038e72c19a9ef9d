// CTagMap serialization round trip (write -> read equal), the registry entry
// the plugin adds, the asString table, and observations inserted.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/matrix_serialization.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/maps/tag_detection_archive.h"
#include "tagmap/obs/CObservationTagPoses.h"

using namespace tagmap;

namespace
{
void expectSameTags(const std::vector<TagDetection>& a, const std::vector<TagDetection>& b)
{
	ASSERT_EQ(a.size(), b.size());
	for (size_t i = 0; i < a.size(); i++)
	{
		EXPECT_EQ(a[i].family, b[i].family);
		EXPECT_EQ(a[i].id, b[i].id);
		EXPECT_EQ(a[i].size, b[i].size);
		EXPECT_TRUE(a[i].pose.matrix() == b[i].pose.matrix());
		EXPECT_TRUE(a[i].covariance == b[i].covariance);
		for (int k = 0; k < 4; k++) EXPECT_TRUE(a[i].corners[k] == b[i].corners[k]);
	}
}
}  // namespace

TEST(MrptTagMap, RegisteredWithMrpt)
{
	const auto* cls = mrpt::rtti::findRegisteredClass("tagmap::maps::CTagMap");
	ASSERT_NE(cls, nullptr);
	EXPECT_TRUE(cls->derivedFrom(CLASS_ID(mrpt::maps::CMetricMap)));
}

TEST(MrptTagMap, SerializationRoundTrip)
{
	const auto tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	m.detectionParams.families = {"tag36h11"};
	m.detectionParams.tagSize = 0.5;
	m.detectionParams.gradient.threshold = 0.1234567890123;  // every digit must survive the YAML text
	m.likelihoodOptions.beaconRangesStd = 0.123;
	m.likelihoodOptions.tagPoseOutlierSigmas = 3.5;
	m.likelihoodOptions.mapTagStdRotationDeg = 0.7;
	m.likelihoodOptions.scoreBeaconRanges = false;
	m.visualOptions.showPoints = false;
	const std::vector<Eigen::Vector3d> stations = {Eigen::Vector3d(0.5, -1.25, 1.5), Eigen::Vector3d(-3, 2, 0.25)};
	m.setPoints(mrpt_test::syntheticWallMap(tags), stations);
	m.setTags(tags);

	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << m;
	buf.Seek(0);
	auto obj = arch.ReadObject();  // by class name, as a viewer would
	auto back = std::dynamic_pointer_cast<maps::CTagMap>(obj);
	ASSERT_TRUE(back);
	expectSameTags(back->tags(), tags);
	EXPECT_EQ(back->points().size(), m.points().size());
	EXPECT_EQ(back->points().getPointsBufferRef_intensity(), m.points().getPointsBufferRef_intensity());
	EXPECT_EQ(back->detectionParams.families, std::vector<std::string>{"tag36h11"});
	EXPECT_EQ(back->detectionParams.tagSize, 0.5);
	EXPECT_EQ(back->detectionParams.gradient.threshold, 0.1234567890123);
	EXPECT_EQ(back->likelihoodOptions.beaconRangesStd, 0.123);
	EXPECT_EQ(back->likelihoodOptions.tagPoseOutlierSigmas, 3.5);
	EXPECT_EQ(back->likelihoodOptions.mapTagStdRotationDeg, 0.7);
	EXPECT_FALSE(back->likelihoodOptions.scoreBeaconRanges);
	EXPECT_FALSE(back->visualOptions.showPoints);
	EXPECT_EQ(back->viewpoints(), stations);  // where the sensors stood (version 5)
}

TEST(MrptTagMap, AsStringIsATable)
{
	maps::CTagMap m;
	m.setTags(mrpt_test::syntheticTags());
	const std::string s = m.asString();
	EXPECT_NE(s.find("3 tags"), std::string::npos);
	EXPECT_NE(s.find("aruco_4x4_50"), std::string::npos);
	EXPECT_NE(s.find("yaw[deg]"), std::string::npos);
}

TEST(MrptTagMap, VisualizationHasOneObjectPerTagPlusPoints)
{
	const auto tags = mrpt_test::syntheticTags();
	maps::CTagMap m;
	m.setPoints(mrpt_test::syntheticWallMap(tags));
	m.setTags(tags);
	mrpt::opengl::CSetOfObjects o;
	m.getVisualizationInto(o);
	EXPECT_EQ(o.size(), tags.size() + 1);
	EXPECT_TRUE(o.getByName("tag36h11:7"));
}

// Files written by tagmap 0.1 (class version 0 of both classes, each with its
// own tag layout) still read. The bytes are written here as 0.1 wrote them.
namespace
{
struct TagMapReader : maps::CTagMap
{
	using maps::CTagMap::serializeFrom;
};
struct TagPosesReader : obs::CObservationTagPoses
{
	using obs::CObservationTagPoses::serializeFrom;
};
}  // namespace

TEST(MrptTagMap, ReadsVersion0)
{
	const auto tags = mrpt_test::syntheticTags();
	mrpt::io::CMemoryStream buf;
	auto out = mrpt::serialization::archiveFrom(buf);
	out << std::string("tag36h11") << 0.5 << std::string("my.yaml");  // detection options
	out << 0.2 << true;  // likelihood options
	out << false << true << true << 3.0;  // visual options
	out << mrpt::maps::TMapGenericParams();
	out << static_cast<uint32_t>(tags.size());
	for (const auto& t : tags) maps::writeTagDetection(out, t);  // 0.1's layout, now layout 0
	out << mrpt::maps::CPointsMapXYZI() << false;
	buf.Seek(0);

	TagMapReader m;
	auto in = mrpt::serialization::archiveFrom(buf);
	m.serializeFrom(in, 0);
	expectSameTags(m.tags(), tags);
	EXPECT_EQ(m.likelihoodOptions.beaconRangesStd, 0.2);
	// The stored choices are resolved; my.yaml is not here, so defaults + choices.
	EXPECT_EQ(m.detectionParams.families, std::vector<std::string>{"tag36h11"});
	EXPECT_EQ(m.detectionParams.tagSize, 0.5);
	EXPECT_EQ(m.visualOptions.pointSize, 3.0);
}

TEST(MrptTagPoses, ReadsVersion0AndRoundTrips)
{
	auto tags = mrpt_test::syntheticTags();
	mrpt::io::CMemoryStream buf;
	auto out = mrpt::serialization::archiveFrom(buf);
	out << std::string("lidar_tags") << mrpt::Clock::fromDouble(3.5) << mrpt::poses::CPose3D(0.1, 0, 1, 0, 0, 0);
	out << static_cast<uint32_t>(tags.size());
	for (const auto& t : tags)
	{
		out << t.family << static_cast<int32_t>(t.id) << t.size;
		out << mrpt::poses::CPose3D(mrpt::math::CMatrixDouble44(t.pose.matrix()));
		out << mrpt::math::CMatrixDouble66(t.covariance);
		out << static_cast<int32_t>(t.pointsUsed) << t.decodeMargin << t.patternFit << t.mirrored;
	}
	buf.Seek(0);
	TagPosesReader o;
	auto in = mrpt::serialization::archiveFrom(buf);
	o.serializeFrom(in, 0);
	EXPECT_EQ(o.sensorLabel, "lidar_tags");
	ASSERT_EQ(o.tags.size(), tags.size());
	for (size_t i = 0; i < tags.size(); i++)
	{
		EXPECT_EQ(o.tags[i].family, tags[i].family);
		EXPECT_EQ(o.tags[i].id, tags[i].id);
		EXPECT_LT((o.tags[i].pose.matrix() - tags[i].pose.matrix()).norm(), 1e-9);
		EXPECT_LT((o.tags[i].corners[2] - tags[i].corners[2]).norm(), 1e-9);
	}

	// The current version keeps every field exactly, corners included.
	mrpt::io::CMemoryStream buf2;
	auto a2 = mrpt::serialization::archiveFrom(buf2);
	a2 << o;
	buf2.Seek(0);
	auto back = a2.ReadObject<obs::CObservationTagPoses>();
	ASSERT_TRUE(back);
	expectSameTags(back->tags, o.tags);
}

// Observations inserted as an MRPT app would (a CMultiMetricMap built from a
// simplemap or rawlog): their points join the map and each one's sensor
// position (robot pose (+) sensor pose) is kept for detection.
TEST(MrptTagMap, InsertedObservationsKeepWhereTheSensorStood)
{
	const mrpt::poses::CPose3D sensor(0.2, 0, 1.1, 0.5, 0, 0);
	const mrpt::poses::CPose3D robots[2] = {mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0),
											mrpt::poses::CPose3D(4, -1, 0, 1.0, 0, 0)};
	maps::CTagMap m;
	for (const mrpt::poses::CPose3D& robot : robots)
	{
		auto cloud = mrpt::maps::CPointsMapXYZI::Create();
		for (int k = 0; k < 10; k++) cloud->insertPointRGB(3.0f + 0.1f * k, 0.5f, 0.2f, 0.5f, 0, 0);
		auto obs = mrpt::obs::CObservationPointCloud::Create();
		obs->pointcloud = cloud;
		obs->sensorPose = sensor;
		EXPECT_TRUE(m.insertObservation(*obs, robot));
	}
	EXPECT_EQ(m.points().size(), 20u);
	ASSERT_EQ(m.viewpoints().size(), 2u);
	for (size_t k = 0; k < 2; k++)
	{
		const mrpt::poses::CPose3D at = robots[k] + sensor;
		EXPECT_NEAR((m.viewpoints()[k] - Eigen::Vector3d(at.x(), at.y(), at.z())).norm(), 0, 1e-9);
	}
	m.clear();
	EXPECT_TRUE(m.viewpoints().empty());
}
