// Single-scan detection and relocalization at 4 m (docs/LOCALIZATION.md):
// one scan of share/scenes/localize_single_scan.yaml, in the sensor frame,
// through the pipeline; the tag's map pose (ground truth) and the seen pose
// give the sensor pose, which must be within 3 cm and 1 degree of the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tagmap/localize/scan_tags.h"
#include "tagmap/localize/tag_relocalization.h"
#include "tagmap/sim/scene_loader.h"
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

/** Simulates one run of the single-scan scene, detects, relocalizes. */
ScanResult relocalizeFromOneScan(const std::string& run, double livoxSeconds)
{
	sim::Scene scene = sim::loadScene(TAGMAP_SOURCE_DIR "/share/scenes/localize_single_scan.yaml",
									  {{"tag_distance", 4.0}, {"livox_seconds", livoxSeconds}});
	scene.runs.erase(std::remove_if(scene.runs.begin(), scene.runs.end(), [&](const sim::ScanRun& r) { return r.name != run; }), scene.runs.end());
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

TEST(LocalizeSingleScan, OusterLike128BeamScanAt4m)
{
	const ScanResult r = relocalizeFromOneScan("ouster", 0.5);
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_EQ(r.seen[0].id, 7);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST(LocalizeSingleScan, LivoxThreeTenthsSecondAt4m)
{
	const ScanResult r = relocalizeFromOneScan("livox", 0.3);
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}

TEST(LocalizeSingleScan, LivoxTenthOfASecondAt4m)
{
	// 10 000 points, ~600 on the tag: the sparsest frame a Livox gives.
	const ScanResult r = relocalizeFromOneScan("livox", 0.1);
	ASSERT_EQ(r.seen.size(), 1u);
	EXPECT_LT(r.translationError, 0.03);
	EXPECT_LT(r.rotationErrorDeg, 1.0);
}
