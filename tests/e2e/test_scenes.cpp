// End-to-end: simulate the project's scenes (share/scenes/) and detect their
// tags with default parameters, scored against the simulator's ground truth
// as the drifted map shows it (truthInMap).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <gtest/gtest.h>

#include "tagmap/io/point_cloud_io.h"
#include "tagmap/local_frame.h"
#include "tagmap/evaluation.h"
#include "tagmap/pipeline.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"
#include "tagmap/tag_family.h"

using namespace tagmap;

namespace
{
struct SceneRun
{
	sim::SimulationOutput sim;
	Detections found;
	Evaluation eval;
};

// A scene of share/scenes, by file name.
sim::Scene shippedScene(const std::string& file, const sim::SceneParameters& overrides = {})
{
	return sim::loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/" + file, overrides);
}

SceneRun run(const std::string& scene, const sim::SceneParameters& overrides = {}, double intensityScale = 1,
			 PipelineParams params = {}, sim::SimOptions opt = {})
{
	SceneRun r;
	opt.intensityScale = intensityScale;
	r.sim = sim::simulate(shippedScene(scene, overrides), opt);
	r.found = Pipeline(params).detect(r.sim.map);
	r.eval = evaluateDetections(r.found.tags, r.sim.truthInMap);
	return r;
}

void expectAllFound(const SceneRun& r)
{
	for (const auto& e : r.eval.perTruth)
	{
		EXPECT_TRUE(e.found) << e.family << ":" << e.id << " missed";
		if (e.found)
		{
			EXPECT_TRUE(e.vertexOrderCorrect) << e.family << ":" << e.id;
		}
	}
	for (const auto& f : r.eval.falseDetections) ADD_FAILURE() << "false detection " << f.family << ":" << f.id;
}

// Where the scene's sensors stood, as the drifted map has them (what a
// simplemap or `--viewpoints` gives the detector).
std::vector<Eigen::Vector3d> stationsOf(const sim::SimulationOutput& out)
{
	std::vector<Eigen::Vector3d> stations;
	for (const sim::FrameData& f : out.frames) stations.push_back(f.driftedPose.translation());
	return stations;
}
}  // namespace

TEST(Scenes, PresentersBothTagsIncludingTheOccludedOne)
{
	const SceneRun r = run("presenters.yaml");
	EXPECT_EQ(r.eval.perTruth.size(), 2u);
	expectAllFound(r);
}

TEST(Scenes, FamiliesEveryTag)
{
	// Every family searched: a read is accepted only if a random pattern
	// would match some code of any searched family that well with
	// probability <= evidence.chance_budget (read_evidence.h). The codes too
	// short or too many for that are then never reported, however cleanly
	// they read: tag16h5 (30 codes of 16 bits), tagCircle21h7, 4x4 ArUco,
	// aruco_original, and the 5x5 dictionaries (searched as 5x5_1000).
	const std::set<std::string> tooWeakAmongAll = {"tag16h5",		 "tagCircle21h7", "aruco_original", "aruco_4x4_50",
													"aruco_4x4_250", "aruco_5x5_100", "aruco_5x5_1000"};
	const SceneRun r = run("families.yaml");
	ASSERT_EQ(r.eval.perTruth.size(), 15u);
	for (const auto& e : r.eval.perTruth)
		EXPECT_EQ(e.found, tooWeakAmongAll.count(e.family) == 0) << e.family << ":" << e.id;
	EXPECT_EQ(r.eval.falsePositives(), 0);
}

TEST(Scenes, FamiliesWeakOnesWhenAskedForAloneWithALargerBudget)
{
	// The user who prints only tag16h5 asks for it alone and accepts more
	// chance matches (--family tag16h5, evidence.chance_budget 0.01).
	// aruco_original is not mirror-safe: the mirror image of its id 23 is its
	// id 848, which reads as cleanly. A map alone cannot tell which face was
	// printed (two codes on one square: neither is reported); the stations
	// it was scanned from can (front_side.h).
	for (const std::string family : {"tag16h5", "tagCircle21h7", "aruco_original", "aruco_4x4_50", "aruco_5x5_1000"})
	{
		PipelineParams p;
		p.families = {family};
		p.evidence.chanceBudget = 0.01;
		SceneRun r = run("families.yaml", {}, 1, p);
		if (family == "aruco_original")
		{
			EXPECT_TRUE(r.found.tags.empty()) << "a mirror-ambiguous read was reported without the stations";
			const std::vector<Eigen::Vector3d> stations = stationsOf(r.sim);
			r.found = Pipeline(p).detect(r.sim.map, stations);
			r.eval = evaluateDetections(r.found.tags, r.sim.truthInMap);
		}
		int found = 0;
		for (const auto& e : r.eval.perTruth) found += e.found && e.family == family;
		EXPECT_EQ(found, 1) << family;
		EXPECT_EQ(r.eval.falsePositives(), 0) << family;
	}
}

// aruco_original 848 is 23 mirrored. Its code cells were once taken from
// ids 0-255, which never turn the id's two highest bits: a printed 848 then
// showed "border errors" and was rejected, and its mirror read, 23, was
// reported: a wrong id. Alone in the map it is ambiguous (nothing reported);
// with the stations it is 848.
TEST(Scenes, AMirrorAmbiguousArucoOriginalIsNeverReportedAsItsMirror)
{
	sim::Scene scene = shippedScene("families.yaml");
	for (sim::TagSpec& t : scene.tags)
		if (t.family == "aruco_original") t.id = 848;
	const sim::SimulationOutput out = sim::simulate(scene);
	PipelineParams p;
	p.families = {"aruco_original"};
	const Detections alone = Pipeline(p).detect(out.map);
	EXPECT_TRUE(alone.tags.empty()) << alone.tags.front().id;
	const std::vector<Eigen::Vector3d> stations = stationsOf(out);
	const Detections seen = Pipeline(p).detect(out.map, stations);
	ASSERT_EQ(seen.tags.size(), 1u);
	EXPECT_EQ(seen.tags.front().id, 848);
}

// aruco_original #1023 is its own image under a half turn: a read of it
// cannot say which corner is its first, so printed upright or upside down
// it gives the same read and one of the two poses would be half a turn off.
// It is judged turn_symmetric and not reported, even where its side is
// known; its neighbour #1022 is reported either way up, vertex order right.
TEST(Scenes, ACodeThatIsItsOwnHalfTurnIsNeverReported)
{
	ASSERT_TRUE(isOwnTurnedImage("aruco_original", 1023));
	for (int id = 0; id < 1023; id++) ASSERT_FALSE(isOwnTurnedImage("aruco_original", id)) << id;
	PipelineParams p;
	p.families = {"aruco_original"};
	for (int id : {1023, 1022})
		for (double turn : {0.0, M_PI})
		{
			sim::Scene scene = shippedScene("families.yaml");
			for (sim::TagSpec& t : scene.tags)
				if (t.family == "aruco_original") t.id = id, t.pose.rotate(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
			const sim::SimulationOutput out = sim::simulate(scene);
			const Detections seen = Pipeline(p).detect(out.map, stationsOf(out));
			const auto turned = std::count_if(seen.candidates.begin(), seen.candidates.end(), [](const CandidateReport& c) {
				return c.verdict == Verdict::TurnSymmetric;
			});
			const Evaluation e = evaluateDetections(seen.tags, out.truthInMap);
			EXPECT_EQ(e.falsePositives(), 0) << id << " " << turn;
			if (id == 1023)
			{
				EXPECT_TRUE(seen.tags.empty()) << turn;
				EXPECT_GE(turned, 1) << turn;
				continue;
			}
			ASSERT_EQ(seen.tags.size(), 1u) << turn;
			EXPECT_EQ(turned, 0) << turn;
			for (const auto& t : e.perTruth)
				if (t.family == "aruco_original")
				{
					EXPECT_TRUE(t.found) << turn;
					EXPECT_TRUE(t.vertexOrderCorrect) << turn;
				}
		}
}

// aruco_5x5_250 #129 is its own mirror image: alone in the map, both of its
// sides read as #129 and the one kept was the mirror read half the time
// (its pose turned 180 deg, vertex order wrong). With the stations the
// mirror read faces away from them; without, neither is reported.
TEST(Scenes, AMirrorSymmetricCodeIsReportedOnlyWhereItsSideIsKnown)
{
	sim::Scene scene = shippedScene("families.yaml");
	for (sim::TagSpec& t : scene.tags)
		if (t.family == "aruco_5x5_100") t.family = "aruco_5x5_250", t.id = 129;
	const sim::SimulationOutput out = sim::simulate(scene);
	PipelineParams p;
	p.families = {"aruco_5x5_250"};
	EXPECT_TRUE(Pipeline(p).detect(out.map).tags.empty());
	const std::vector<Eigen::Vector3d> stations = stationsOf(out);
	const Evaluation e = evaluateDetections(Pipeline(p).detect(out.map, stations).tags, out.truthInMap);
	int found = 0;
	for (const auto& t : e.perTruth)
		if (t.family == "aruco_5x5_250")
		{
			found += t.found;
			EXPECT_TRUE(t.vertexOrderCorrect);
		}
	EXPECT_EQ(found, 1);
	EXPECT_EQ(e.falsePositives(), 0);
}

TEST(Scenes, NegativesNoFalseDetection)
{
	const SceneRun r = run("negatives.yaml");
	EXPECT_TRUE(r.eval.perTruth.empty());
	EXPECT_EQ(r.found.tags.size(), 0u);
}

// A mirror-printed tag36h11 on a pillar scanned from all sides: its mirror
// image is a valid code whose printed face would look into the pillar.
// front_side.h rejects it; without that check it is a false tag (so the
// scene does exercise the rule).
TEST(Scenes, MirrorPrintedTagOnAPillarIsNoTag)
{
	const SceneRun r = run("mirrored.yaml");
	EXPECT_EQ(r.eval.perTruth.size(), 1u);
	expectAllFound(r);
	const auto wrongSide = std::count_if(r.found.candidates.begin(), r.found.candidates.end(),
										 [](const CandidateReport& c) { return c.verdict == Verdict::WrongSide; });
	EXPECT_GE(wrongSide, 1);

	PipelineParams unchecked;
	unchecked.frontSide.enabled = false;
	const Detections without = Pipeline(unchecked).detect(r.sim.map);
	const auto mirrored = std::count_if(without.tags.begin(), without.tags.end(),
										[](const TagDetection& t) { return t.family == "tag36h11" && t.id == 200; });
	EXPECT_EQ(mirrored, 1) << "the scene no longer shows the mirror read the check is for";

	// Knowing where the stations stood changes nothing here: tag 5 is seen.
	const std::vector<Eigen::Vector3d> stations = stationsOf(r.sim);
	const Detections withStations = Pipeline().detect(r.sim.map, stations);
	EXPECT_EQ(evaluateDetections(withStations.tags, r.sim.truthInMap).falsePositives(), 0);
	EXPECT_EQ(withStations.tags.size(), 1u);
}

// The same pillar scanned from its west station only: nothing in the map
// lies in front of the mirror read's face (the pillar's inside and far
// side were never scanned), so a point cloud alone cannot tell and the
// read is reported. Where the station's position is known (a simplemap or
// rawlog; front_side.h, seenOnlyFromBehind) no line from that face reaches
// it, while one from the sheet's back does: no tag.
TEST(Scenes, MirrorPrintedTagScannedFromOneSideIsNoTagWhereTheStationIsKnown)
{
	sim::Scene scene = shippedScene("mirrored.yaml");
	ASSERT_EQ(scene.runs.size(), 1u);
	scene.runs[0].waypoints.resize(1);  // the west station, in front of the sheet
	const sim::SimulationOutput s = sim::simulate(scene, {});
	const std::vector<Eigen::Vector3d> stations = stationsOf(s);
	ASSERT_FALSE(stations.empty());
	const auto mirrorReads = [](const Detections& d) {
		return std::count_if(d.tags.begin(), d.tags.end(),
							 [](const TagDetection& t) { return t.family == "tag36h11" && t.id == 200; });
	};
	EXPECT_EQ(mirrorReads(Pipeline().detect(s.map)), 1) << "the points alone no longer show the one-sided case";
	const Detections known = Pipeline().detect(s.map, stations);
	EXPECT_EQ(mirrorReads(known), 0);
	EXPECT_TRUE(known.tags.empty());
	EXPECT_TRUE(std::any_of(known.candidates.begin(), known.candidates.end(),
							[](const CandidateReport& c) { return c.verdict == Verdict::WrongSide; }));
}

TEST(Scenes, ParkingAllThreeTagsIncludingTheBlurredOne)
{
	// Tags 1 and 4 (the slow pass) and tag 0: passed fast with the LiDAR
	// swinging, 4x drift and poor deskewing, the case the paper misses. It
	// is read by the soft decoder on a fitted border square and checked
	// against a blurred bitmap; over seeds 1-6 it is found in 5 (not 4).
	// Given its family, as a user who printed them would: with every family
	// searched, the blurred tag's read (2 of 36 bits wrong) is as likely by
	// chance as the budget allows a read among 13 families (read_evidence.h).
	PipelineParams p;
	p.families = {"aruco_6x6_250"};
	const SceneRun r = run("parking.yaml", {}, 1, p);
	expectAllFound(r);
	EXPECT_EQ(r.eval.falsePositives(), 0);
}

TEST(Scenes, DenseNoisyWalkByOverSixSeeds)
{
	// share/scenes/dense_walk.yaml at 1.5 M points: a multi-pass map whose
	// 1.8 cm range noise and per-pass intensity levels a fine image
	// resolves. Measured over seeds 1-6: 12 of the 12 tags since the
	// simulator's tilted boards lean on the wall instead of sinking into it
	// (10 before, with the image edge capped at 200 pixels; 8 at 1200);
	// never a false one. One seed's luck moves a tag either way, so the bar
	// is the six seeds' total, one below what was measured.
	int found = 0, tags = 0;
	for (uint64_t seed = 1; seed <= 6; seed++)
	{
		sim::SimOptions opt;
		opt.seed = seed;
		opt.targetPoints = 1500000;
		const SceneRun r = run("dense_walk.yaml", {}, 1, {}, opt);
		for (const auto& e : r.eval.perTruth) found += e.found, tags++;
		EXPECT_EQ(r.eval.falsePositives(), 0) << "seed " << seed;
	}
	EXPECT_EQ(tags, 12);
	EXPECT_GE(found, 11);
}

TEST(Scenes, SingleStationaryScanAtFourMetres)
{
	const SceneRun r = run("accuracy.yaml", {{"tag_distance", 4.0}});
	expectAllFound(r);
	ASSERT_EQ(r.eval.found(), 1);
	EXPECT_LT(r.eval.perTruth[0].maxCornerError, 0.005);
}

TEST(Scenes, IntensityScaleGivesIdenticalTags)
{
	std::vector<std::vector<TagDetection>> results;
	for (double scale : {1.0, 255.0, 65535.0}) results.push_back(run("presenters.yaml", {}, scale).found.tags);
	for (size_t k = 1; k < results.size(); k++)
	{
		ASSERT_EQ(results[k].size(), results[0].size());
		for (size_t t = 0; t < results[0].size(); t++)
		{
			EXPECT_EQ(results[k][t].family, results[0][t].family);
			EXPECT_EQ(results[k][t].id, results[0][t].id);
			for (int c = 0; c < 4; c++) EXPECT_LT((results[k][t].corners[c] - results[0][t].corners[c]).norm(), 1e-5);
		}
	}
}

namespace
{
/** Largest corner distance between two results of the same tags (same
 *  order), after moving `b` by -shift; fails if the tags differ. */
double maxCornerDifference(const std::vector<TagDetection>& a, const std::vector<TagDetection>& b,
						   const Eigen::Vector3d& shift)
{
	EXPECT_EQ(a.size(), b.size());
	double worst = 0;
	for (size_t t = 0; t < std::min(a.size(), b.size()); t++)
	{
		EXPECT_EQ(a[t].family, b[t].family);
		EXPECT_EQ(a[t].id, b[t].id);
		for (int c = 0; c < 4; c++) worst = std::max(worst, (b[t].corners[c] - shift - a[t].corners[c]).norm());
	}
	return worst;
}

/** Reads a map file as `tagmap detect` does and returns its tags in the file's frame. */
std::vector<TagDetection> detectFile(const std::string& path, const io::LoadParams& params = {})
{
	io::LoadReport load;
	const auto map = io::loadPointCloud(path, &load, params);
	return translatedTags(Pipeline().detect(map).tags, load.origin);
}
}  // namespace

TEST(Scenes, GeoreferencedMapsGiveTheShiftedTags)
{
	const sim::SimulationOutput s =
		sim::simulate(shippedScene("presenters.yaml"), {});
	const std::string dir = std::string(TAGMAP_BINARY_DIR) + "/test_scenes_geo";
	std::filesystem::create_directories(dir);
	const Eigen::Vector3d shift(512345, 5123456, 187);
	io::savePcdBinary(dir + "/plain.pcd", s.map);
	io::savePcdBinary(dir + "/utm.pcd", s.map, shift);
	io::LasWriteParams las;
	las.pointFormat = 7;
	las.shift = shift;
	io::saveLas(dir + "/utm.las", s.map, las);

	const std::vector<TagDetection> plain = detectFile(dir + "/plain.pcd");
	ASSERT_EQ(plain.size(), 2u);
	const double pcd = maxCornerDifference(plain, detectFile(dir + "/utm.pcd"), shift);
	const double lasError = maxCornerDifference(plain, detectFile(dir + "/utm.las"), shift);
	// With the shift itself as the origin the local frame is the unshifted
	// one: float64 keeps every float32 coordinate exactly, so the tags are
	// the same but for the double rounding of adding the shift back (1e-9 m
	// at 5e6 m); the chosen origin differs from the shift by the
	// map's rounded median, and the pipeline's float arithmetic on a
	// translated map differs a little. LAS stores millimetre steps: every
	// point moves by up to 0.5 mm, and the occluded tag 7, whose error
	// against the truth is several mm, moves by up to 1.4 mm (measured).
	// A lost float64 digit would show as centimetres.
	io::LoadParams asShift;
	asShift.fixedOrigin = true;
	asShift.origin = shift;
	const double pcdAtShift = maxCornerDifference(plain, detectFile(dir + "/utm.pcd", asShift), shift);
	std::cout << "shifted by (512345, 5123456, 187) m: max corner error PCD float64 " << pcd * 1000
			  << " mm (origin = shift: " << pcdAtShift * 1000 << " mm), LAS format 7 (1 mm steps) " << lasError * 1000
			  << " mm\n";
	EXPECT_LT(pcd, 0.001);
	EXPECT_LT(pcdAtShift, 1e-8);
	EXPECT_LT(lasError, 0.002);
}

TEST(Scenes, FarOutliersChangeNothing)
{
	SceneRun clean = run("presenters.yaml");
	ASSERT_EQ(clean.found.tags.size(), 2u);
	// 20 stray returns 1000-2000 km away in every direction (multipath,
	// false returns): the neighbour index must not care.
	mrpt::maps::CPointsMapXYZI map = clean.sim.map;
	for (int k = 0; k < 20; k++)
	{
		const double r = 1e6 + 5e4 * k, a = 0.7 * k, b = 0.3 * k - 3;
		map.insertPointFast(static_cast<float>(r * std::cos(a) * std::cos(b)), static_cast<float>(r * std::sin(a) * std::cos(b)),
							static_cast<float>(r * std::sin(b)));
		map.setPointIntensity(map.size() - 1, static_cast<float>(k % 3));
	}
	map.mark_as_modified();
	const Detections withOutliers = Pipeline().detect(map);
	const double diff = maxCornerDifference(clean.found.tags, withOutliers.tags, Eigen::Vector3d::Zero());
	std::cout << "20 outliers at 1000-2000 km: " << withOutliers.tags.size() << " tags, max corner difference "
			  << diff * 1000 << " mm\n";
	// Not bit-identical: 20 more points move the strided samples of the
	// spacing estimate and the intensity percentiles a little.
	EXPECT_LT(diff, 0.002);
}
