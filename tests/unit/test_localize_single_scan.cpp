// Single-scan detection and relocalization at 4 m (docs/LOCALIZATION.md):
// one scan of share/scenes/localize_single_scan.yaml, in the sensor frame,
// through the pipeline; the tag's map pose (ground truth) and the seen pose
// give the sensor pose, which must be within 3 cm and 1 degree of the truth.
// Each scan goes through the map path (stages 1-3 on the intensity gradient)
// and through the sensor's own view (sensor_view.h), which must do as well.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "tagmap/localize/observe_rawlog.h"
#include "tagmap/localize/rawlog_visit.h"
#include "tagmap/localize/scan_tags.h"
#include "tagmap/localize/tag_relocalization.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/sim_rawlog.h"
#include "tagmap/sim/sim_outputs.h"
#include "tagmap/sim/simulate.h"

using namespace tagmap;

namespace
{
struct ScanResult
{
	size_t points = 0;
	std::vector<TagDetection> seen;
	double translationError = NAN, rotationErrorDeg = NAN;
};

/** Simulates one run of the single-scan scene, detects, relocalizes;
 *  `turnDeg` turns the sensor about its vertical axis first (180: the tag
 *  is behind it, across the seam of a spinning scan's azimuth). */
ScanResult relocalizeFromOneScan(const std::string& run, double livoxSeconds, bool sensorView, double turnDeg = 0)
{
	sim::Scene scene = sim::loadScene(TAGMAP_SOURCE_DIR "/share/scenes/localize_single_scan.yaml",
									  {{"tag_distance", 4.0}, {"livox_seconds", livoxSeconds}});
	scene.runs.erase(std::remove_if(scene.runs.begin(), scene.runs.end(), [&](const sim::ScanRun& r) { return r.name != run; }), scene.runs.end());
	if (turnDeg != 0)
		for (sim::SceneObject& o : scene.objects)
			if (o.name == "floor")
			{
				// Floor all round (the scene's stops 2.5 m behind the sensor), so
				// the scan covers every azimuth and its view has a seam.
				o.faces.front().pose.translation().x() = 0;
				o.faces.front().halfW = o.faces.front().halfH = 10;
			}
	for (sim::Waypoint& w : scene.runs.front().waypoints)
		w.pose.linear() = w.pose.linear() * Eigen::AngleAxisd(turnDeg * M_PI / 180, Eigen::Vector3d::UnitZ()).matrix();
	sim::SimOptions opt;
	opt.seed = 3;
	opt.threads = 2;
	const sim::SimulationOutput out = sim::simulate(scene, opt);

	// The whole run as one scan in the sensor frame (a Livox run is cut into
	// 0.1 s frames; the sensor stands still, so they stack exactly).
	mrpt::maps::CPointsMapXYZI scan;
	const mrpt::maps::CSimpleMap keyframes = sim::toSimpleMap(out);
	for (size_t k = 0; k < keyframes.size(); k++)
		for (const auto& obs : *keyframes.getAsPair(k).sf)
		{
			const auto frame = localize::scanInSensorFrame(*obs);
			EXPECT_TRUE(frame);
			if (frame) scan.insertAnotherMap(&*frame, mrpt::poses::CPose3D());
		}

	PipelineParams params = localize::singleScanPipelineParams();
	params.families = {"tag36h11"};
	params.threads = 2;
	params.sensorView.enabled = sensorView;
	ScanResult r;
	r.points = scan.size();
	r.seen = localize::detectTagsInScan(Pipeline(params), scan);
	const auto fix = localize::relocalize(out.truth, r.seen);
	if (!fix) return r;
	const Eigen::Isometry3d& truth = out.frames.front().truePose;
	r.translationError = (fix->pose.translation() - truth.translation()).norm();
	r.rotationErrorDeg = Eigen::AngleAxisd(truth.linear().transpose() * fix->pose.linear()).angle() * 180 / M_PI;
	std::printf("%s: %zu points, %zu tag(s), sensor pose error %.4f m, %.3f deg (std %.4f m, %.3f deg)\n", run.c_str(),
				r.points, r.seen.size(), r.translationError, r.rotationErrorDeg, std::sqrt(fix->covariance(0, 0)),
				std::sqrt(fix->covariance(5, 5)) * 180 / M_PI);
	return r;
}
}  // namespace

// Both ways of proposing candidates in a scan: the map path's and the
// sensor view's.
class LocalizeSingleScan : public ::testing::TestWithParam<bool>
{
};
INSTANTIATE_TEST_SUITE_P(Paths, LocalizeSingleScan, ::testing::Values(false, true),
						 [](const ::testing::TestParamInfo<bool>& path) { return path.param ? "SensorView" : "MapPath"; });

TEST_P(LocalizeSingleScan, OusterLike128BeamScanAt4m)
{
	const ScanResult r = relocalizeFromOneScan("ouster", 0.5, GetParam());
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_EQ(r.seen[0].id, 7);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST_P(LocalizeSingleScan, LivoxThreeTenthsSecondAt4m)
{
	const ScanResult r = relocalizeFromOneScan("livox", 0.3, GetParam());
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST_P(LocalizeSingleScan, LivoxTenthOfASecondAt4m)
{
	// 10 000 points, ~600 on the tag: the sparsest frame a Livox gives.
	const ScanResult r = relocalizeFromOneScan("livox", 0.1, GetParam());
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST(LocalizeSingleScanSensorView, ATagAcrossTheAzimuthSeamIsReadWhole)
{
	// The sensor turned round: the tag lies behind it, at azimuth +-180 deg,
	// where a spinning scan's view is cut; the view repeats the azimuths
	// past the cut, so the tag is whole on one side.
	const ScanResult r = relocalizeFromOneScan("ouster", 0.5, true, 180);
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_EQ(r.seen[0].id, 7);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST(LocalizeSingleScanSensorView, OneScanIsReadFromItsViewAWindowThroughTheMapPath)
{
	// A scan has one viewpoint; scans merged over a moving window do not.
	EXPECT_TRUE(localize::singleScanPipelineParams().sensorView.enabled);
	EXPECT_TRUE(localize::singleScanPipelineParams(1).sensorView.enabled);
	EXPECT_FALSE(localize::singleScanPipelineParams(3).sensorView.enabled);
}

// A mirror-printed sheet on a pillar, scanned from its west station only
// (share/scenes/mirrored.yaml): its mirror image reads as tag36h11 200 with
// the printed face into the pillar, which nothing in the scan contradicts.
// observe knows where the sensor stood (the scan's origin): no line from
// that face reaches it (front_side.h), so even its map path, which decodes
// both sides of every quad, reports no tag.
TEST(LocalizeSingleScan, ObserveReportsNoMirrorImageOfASheetScannedFromTheFront)
{
	sim::Scene scene = sim::loadScene(TAGMAP_SOURCE_DIR "/share/scenes/mirrored.yaml");
	ASSERT_EQ(scene.runs.size(), 1u);
	scene.runs[0].waypoints.resize(1);  // the west station, in front of the sheet
	const sim::SimulationOutput s = sim::simulate(scene, {});
	ASSERT_EQ(s.frames.size(), 1u);
	PipelineParams params = localize::singleScanPipelineParams(1);
	params.sensorView.enabled = false;
	const Pipeline pipeline(params);
	// The scan alone, as the pipeline saw it before it knew the sensor.
	const mrpt::obs::CRawlog rawlog = sim::toRawlog(s);
	std::optional<mrpt::maps::CPointsMapXYZI> scan;
	localize::visitRawlog(rawlog, {{},
								   [&](const mrpt::obs::CSensoryFrame& sf) {
									   for (const auto& o : sf)
										   if (!scan) scan = localize::scanInSensorFrame(*o);
								   },
								   [&](const mrpt::obs::CObservation::Ptr& o) {
									   if (!scan) scan = localize::scanInSensorFrame(*o);
								   }});
	ASSERT_TRUE(scan.has_value());
	const Detections alone = pipeline.detect(*scan);
	EXPECT_EQ(std::count_if(alone.tags.begin(), alone.tags.end(), [](const TagDetection& t) { return t.id == 200; }), 1)
		<< "the scan alone no longer shows the mirror read";
	localize::ObserveReport report;
	localize::observeRawlog(rawlog, pipeline, {}, &report);
	EXPECT_EQ(report.scans, 1u);
	EXPECT_EQ(report.tagsSeen, 0u);
}

// observe --max-window: a tag too far for a short window is found once the
// frames that saw nothing are detected again over the longer one. A Livox
// frame of 0.1 s at 16 m puts ~40 points on a 0.5 m tag36h11; the sensor
// stands still, so its odometry places the frames exactly.
TEST(LocalizeSingleScan, AScanWhoseShortWindowSeesNothingTriesTheLongOne)
{
	sim::Scene scene = sim::loadScene(TAGMAP_SOURCE_DIR "/share/scenes/localize_single_scan.yaml",
									  {{"tag_distance", 16.0}, {"livox_seconds", 1.0}});
	scene.runs.erase(std::remove_if(scene.runs.begin(), scene.runs.end(), [&](const sim::ScanRun& r) { return r.name != "livox"; }), scene.runs.end());
	sim::SimOptions opt;
	opt.seed = 3;
	opt.threads = 2;
	const mrpt::obs::CRawlog rawlog = sim::toRawlog(sim::simulate(scene, opt));
	PipelineParams params = localize::singleScanPipelineParams(2);
	params.families = {"tag36h11"};
	params.threads = 2;
	const Pipeline pipeline(params);
	localize::ObserveParams shortOnly;
	shortOnly.window = 2;
	localize::ObserveReport alone, grown;
	localize::observeRawlog(rawlog, pipeline, shortOnly, &alone);
	localize::ObserveParams growing = shortOnly;
	growing.maxWindow = 8;
	localize::observeRawlog(rawlog, pipeline, growing, &grown);
	std::printf("scans %zu: window 2 saw the tag in %zu, up to 8 in %zu\n", alone.scans, alone.scansWithTags,
				grown.scansWithTags);
	ASSERT_EQ(alone.scans, 10u);
	EXPECT_EQ(alone.scansWithTags, 0u) << "the short window already sees the tag: nothing left to test";
	EXPECT_GE(grown.scansWithTags, 3u);
	EXPECT_EQ(grown.scansWithTagsInLongWindow, grown.scansWithTags);
	for (size_t k = 0; k < grown.perScan.size(); k++)
		EXPECT_LE(grown.perScan[k].scansMerged, std::min<size_t>(k + 1, 8)) << "scan " << k;
	// A scan that saw the tag used the long window; the first one has no
	// earlier scans to merge.
	EXPECT_EQ(grown.perScan[0].scansMerged, 1u);
	EXPECT_GT(grown.perScan.back().scansMerged, 2u);
}
