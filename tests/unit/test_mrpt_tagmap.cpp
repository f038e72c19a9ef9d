// CTagMap serialization round trip (write -> read equal), the registry entry
// the plugin adds, and the asString table.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/maps/CTagMap.h"

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
	m.detectionOptions.families = "tag36h11";
	m.detectionOptions.tagSize = 0.5;
	m.likelihoodOptions.beaconRangesStd = 0.123;
	m.visualOptions.showPoints = false;
	m.setPoints(mrpt_test::syntheticWallMap(tags));
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
	EXPECT_EQ(back->detectionOptions.families, "tag36h11");
	EXPECT_EQ(back->detectionOptions.tagSize, 0.5);
	EXPECT_EQ(back->likelihoodOptions.beaconRangesStd, 0.123);
	EXPECT_FALSE(back->visualOptions.showPoints);
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
