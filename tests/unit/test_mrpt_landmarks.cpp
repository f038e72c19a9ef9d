// CLandmarksMap content: one featBeacon per tag with the encoded ID, the tag
// centre, its normal and the position covariance; and the .gz file reloads.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/landmarks_map.h"

using namespace tagmap;

TEST(MrptLandmarks, OneBeaconPerTag)
{
	const auto tags = mrpt_test::syntheticTags();
	const auto lm = mrpt_bridge::tagsToLandmarksMap(tags);
	ASSERT_EQ(lm.landmarks.size(), tags.size());
	for (size_t i = 0; i < tags.size(); i++)
	{
		const auto* l = lm.landmarks.get(static_cast<unsigned>(i));
		const auto& t = tags[i];
		EXPECT_EQ(l->getType(), mrpt::vision::featBeacon);
		EXPECT_EQ(l->ID, mrpt_bridge::encodeBeaconId(t.family, t.id));
		EXPECT_NEAR(l->pose_mean.x, t.position().x(), 1e-9);
		EXPECT_NEAR(l->pose_mean.y, t.position().y(), 1e-9);
		EXPECT_NEAR(l->pose_mean.z, t.position().z(), 1e-9);
		EXPECT_NEAR(l->normal.x, -1.0, 1e-9);  // synthetic tags face -x
		EXPECT_FLOAT_EQ(l->pose_cov_11, static_cast<float>(t.covariance(0, 0)));
		EXPECT_FLOAT_EQ(l->pose_cov_33, static_cast<float>(t.covariance(2, 2)));
		EXPECT_NE(lm.landmarks.getByBeaconID(static_cast<unsigned>(l->ID)), nullptr);
	}
}

TEST(MrptLandmarks, GzFileReloads)
{
	const std::string path = std::string(TAGMAP_BINARY_DIR) + "/test_mrpt_landmarks.gz";
	const auto tags = mrpt_test::syntheticTags();
	mrpt_bridge::writeLandmarksMap(path, tags);
	mrpt::maps::CLandmarksMap back;
	mrpt::io::CFileGZInputStream f(path);
	mrpt::serialization::archiveFrom(f) >> back;
	ASSERT_EQ(back.landmarks.size(), tags.size());
	EXPECT_EQ(back.landmarks.get(2)->ID, mrpt_bridge::encodeBeaconId("aruco_4x4_50", 3));
}
