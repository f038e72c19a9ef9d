// The --ini output parsed back by MRPT itself: CMultiMetricMap builds a
// CLandmarksMap with every tag as a beacon, and (the plugin being linked, so
// loaded) a CTagMap holding the full tags.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CLandmarksMap.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/metric_map_ini.h"

using namespace tagmap;

TEST(MrptIni, ParsedByCMultiMetricMap)
{
	const auto tags = mrpt_test::syntheticTags();
	mrpt_bridge::MetricMapIniParams p;
	p.tagMapDetectionOptions = {{"families", "tag36h11"}, {"tagSize", "0.5"}};
	mrpt::config::CConfigFileMemory ini(mrpt_bridge::metricMapIni(tags, p));

	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "MetricMap");
	mrpt::maps::CMultiMetricMap mm;
	mm.setListOfMaps(inits);
	ASSERT_EQ(mm.maps.size(), 2u);

	auto lm = mm.mapByClass<mrpt::maps::CLandmarksMap>();
	ASSERT_TRUE(lm);
	ASSERT_EQ(lm->landmarks.size(), tags.size());
	for (const auto& t : tags)
	{
		const auto* l = lm->landmarks.getByBeaconID(static_cast<unsigned>(mrpt_bridge::encodeBeaconId(t.family, t.id)));
		ASSERT_NE(l, nullptr) << t.family << " #" << t.id;
		EXPECT_NEAR(l->pose_mean.x, t.position().x(), 1e-6);
		EXPECT_NEAR(l->pose_mean.z, t.position().z(), 1e-6);
	}
	EXPECT_FLOAT_EQ(lm->likelihoodOptions.beaconRangesStd, 0.08f);

	auto tm = mm.mapByClass<maps::CTagMap>();
	ASSERT_TRUE(tm);
	EXPECT_TRUE(tm->genericMapParams.enableObservationLikelihood);  // the tag poses
	EXPECT_FALSE(tm->likelihoodOptions.scoreBeaconRanges);  // the landmarksMap scores ranges
	EXPECT_EQ(tm->likelihoodOptions.tagPoseExtraStdPosition, 0.1);
	EXPECT_EQ(tm->likelihoodOptions.tagPoseExtraStdRotationDeg, 2);
	EXPECT_EQ(tm->detectionParams.families, std::vector<std::string>{"tag36h11"});
	EXPECT_EQ(tm->detectionParams.tagSize, 0.5);
	ASSERT_EQ(tm->tags().size(), tags.size());
	for (size_t i = 0; i < tags.size(); i++)
	{
		EXPECT_EQ(tm->tags()[i].family, tags[i].family);
		EXPECT_TRUE(tm->tags()[i].pose.isApprox(tags[i].pose, 1e-12));
		EXPECT_TRUE(tm->tags()[i].covariance == tags[i].covariance);
	}
}

TEST(MrptIni, StockMrptIgnoresTagMapSection)
{
	// Without a "tagMap_count", a stock MRPT sees only the landmarks map.
	mrpt_bridge::MetricMapIniParams p;
	p.includeTagMap = false;
	mrpt::config::CConfigFileMemory ini(mrpt_bridge::metricMapIni(mrpt_test::syntheticTags(), p));
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "MetricMap");
	EXPECT_EQ(inits.size(), 1u);
}
