// End-to-end: simulate the project's scenes (share/scenes/) and detect their
// tags with default parameters, scored against the simulator's ground truth
// as the drifted map shows it (truthInMap).
#include <set>
#include <gtest/gtest.h>

#include "tagmap/evaluation.h"
#include "tagmap/pipeline.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"

using namespace tagmap;

namespace
{
struct SceneRun
{
	sim::SimulationOutput sim;
	Detections found;
	Evaluation eval;
};

SceneRun run(const std::string& scene, const sim::SceneParameters& overrides = {}, double intensityScale = 1,
			 PipelineParams params = {})
{
	SceneRun r;
	sim::SimOptions opt;
	opt.intensityScale = intensityScale;
	r.sim = sim::simulate(sim::loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/" + scene, overrides), opt);
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
	for (const std::string family : {"tag16h5", "tagCircle21h7", "aruco_original", "aruco_4x4_50", "aruco_5x5_1000"})
	{
		PipelineParams p;
		p.families = {family};
		p.evidence.chanceBudget = 0.01;
		const SceneRun r = run("families.yaml", {}, 1, p);
		int found = 0;
		for (const auto& e : r.eval.perTruth) found += e.found && e.family == family;
		EXPECT_EQ(found, 1) << family;
		EXPECT_EQ(r.eval.falsePositives(), 0) << family;
	}
}

TEST(Scenes, NegativesNoFalseDetection)
{
	const SceneRun r = run("negatives.yaml");
	EXPECT_TRUE(r.eval.perTruth.empty());
	EXPECT_EQ(r.found.tags.size(), 0u);
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
