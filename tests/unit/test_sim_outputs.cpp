// What `tagmap simulate` writes reads back through tagmap::io: the PCD is the
// map, the simplemap's keyframes merged at their (drifted) poses are the same
// map, the ground truth round-trips, the TUM files have one line per frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tagmap/io/point_cloud_io.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/sim_outputs.h"
#include "tagmap/sim/simulate.h"
#include "tagmap/tags_json.h"

using namespace tagmap;

TEST(SimOutputs, FilesReadBackConsistently)
{
	const auto scene = sim::loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/presenters.yaml");
	sim::SimOptions opt;
	opt.intensityScale = 255;
	const auto out = sim::simulate(scene, opt);
	const auto dir = std::filesystem::temp_directory_path() / "tagmap_test_sim_outputs";
	std::filesystem::remove_all(dir);
	sim::writeSimulationOutputs(dir.string(), out, {true, opt.seed});

	const auto pcd = io::loadPointCloud((dir / "map.pcd").string());
	ASSERT_EQ(pcd.size(), out.map.size());
	const auto sm = io::loadPointCloud((dir / "scans.simplemap").string());
	ASSERT_EQ(sm.size(), out.map.size());
	double worst = 0;
	for (size_t i = 0; i < pcd.size(); i += 97)
	{
		float ax, ay, az, bx, by, bz;
		pcd.getPointFast(i, ax, ay, az);
		sm.getPointFast(i, bx, by, bz);
		worst = std::max<double>(worst, (Eigen::Vector3f(ax, ay, az) - Eigen::Vector3f(bx, by, bz)).norm());
		EXPECT_EQ(pcd.getPointIntensity(i), out.map.getPointIntensity(i));
	}
	EXPECT_LT(worst, 1e-4);

	const auto truth = readTagsJson((dir / "ground_truth.json").string());
	ASSERT_EQ(truth.size(), out.truth.size());
	for (size_t t = 0; t < truth.size(); t++)
		for (int v = 0; v < 4; v++) EXPECT_LT((truth[t].corners[v] - out.truth[t].corners[v]).norm(), 1e-5);

	for (const char* f : {"trajectory_true.tum", "trajectory_drifted.tum"})
	{
		std::ifstream in(dir / f);
		size_t lines = 0;
		for (std::string l; std::getline(in, l);) lines++;
		EXPECT_EQ(lines, out.frames.size()) << f;
	}
	std::filesystem::remove_all(dir);
}
