// What `tagmap simulate` writes reads back through tagmap::io: the PCD is the
// map, the simplemap's keyframes merged at their (drifted) poses are the same
// map, the ground truth round-trips, the TUM files have one line per frame.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tagmap/evaluation.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/sim_outputs.h"
#include "tagmap/sim/sim_rawlog.h"
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

	// Each tag's sighting conditions, as the truth file gives them to
	// `tagmap compare --conditions`: presenters' two tags at 2-6 m.
	const std::string gt = (dir / "ground_truth.json").string();
	const auto perCell = readTruthNumbers(gt, "points_per_cell"), near = readTruthNumbers(gt, "range_min"),
			   far = readTruthNumbers(gt, "range_max");
	ASSERT_EQ(perCell.size(), out.tagSightings.size());
	for (size_t t = 0; t < out.tagSightings.size(); t++)
	{
		const sim::TagSighting& s = out.tagSightings[t];
		EXPECT_GT(s.pointsInSquare, 0u);
		EXPECT_LE(s.pointsInSquare, s.points);
		EXPECT_NEAR(perCell[t], s.pointsInSquare / 64.0, 0.01);  // tag36h11: 8 x 8 cells
		EXPECT_GT(near[t], 1.0);
		EXPECT_LT(far[t], 8.0);
		EXPECT_LE(near[t], far[t]);
		EXPECT_GE(s.scans, 1);
		EXPECT_LE(s.scans, static_cast<int>(out.frames.size()));
	}
	EXPECT_TRUE(std::isnan(readTruthNumbers(gt, "no_such_field").at(0)));

	for (const char* f : {"trajectory_true.tum", "trajectory_drifted.tum"})
	{
		std::ifstream in(dir / f);
		size_t lines = 0;
		for (std::string l; std::getline(in, l);) lines++;
		EXPECT_EQ(lines, out.frames.size()) << f;
	}
	std::filesystem::remove_all(dir);
}

// A sensor mounted on a robot base (run `mount`): the rawlog's odometry moves
// the base along the waypoints and every scan's sensor pose is the mount, so
// base (+) sensorPose is the true sensor pose a localizer must recover.
TEST(SimOutputs, MountedSensorRawlogHasTheBaseOdometryAndTheMount)
{
	const auto scene = sim::parseScene(R"(
name: mounted
objects:
  - {name: wall, type: plane, position: [6, 0, 1], normal: [-1, 0, 0], size: [8, 3], reflectivity: 0.5}
sensors:
  - {name: s, type: spinning, beams: 16, vertical_fov_deg: [-15, 15], columns: 256, rev_per_second: 10}
runs:
  - name: drive
    sensor: s
    mount: {position: [0.3, 0.15, 1.0], rpy_deg: [0, 0, 90]}
    waypoints:
      - {t: 0, position: [0, 0, 0], rpy_deg: [0, 0, 0]}
      - {t: 1, position: [1, 0, 0], rpy_deg: [0, 0, 20]}
)",
										 "mounted");
	sim::SimOptions opt;
	const auto out = sim::simulate(scene, opt);
	ASSERT_GE(out.frames.size(), 5u);
	const mrpt::obs::CRawlog log = sim::toRawlog(out);
	mrpt::poses::CPose2D odometry;
	size_t frame = 0;
	for (size_t i = 0; i < log.size(); i++)
	{
		if (log.getType(i) == mrpt::obs::CRawlog::etActionCollection)
		{
			const auto move = log.getAsAction(i)->getBestMovementEstimation();
			ASSERT_TRUE(move);
			odometry = odometry + move->poseChange->getMeanVal();
			continue;
		}
		const auto sf = log.getAsObservations(i);
		ASSERT_EQ(sf->size(), 1u);
		mrpt::poses::CPose3D sensorOnBase;
		sf->getObservationByIndex(0)->getSensorPose(sensorOnBase);
		EXPECT_NEAR(sensorOnBase.x(), 0.3, 1e-9);
		EXPECT_NEAR(sensorOnBase.y(), 0.15, 1e-9);
		EXPECT_NEAR(sensorOnBase.z(), 1.0, 1e-9);
		EXPECT_NEAR(sensorOnBase.yaw(), M_PI / 2, 1e-9);
		// The odometry is the base's motion since the first frame (up to the
		// scene's default drift, mm over 1 m), not the sensor's, which swings
		// 0.3 m ahead of it as the base turns.
		const auto planarBase = [&](size_t k) {
			const Eigen::Isometry3d b = out.frames[k].truePose * out.frames[k].mount.inverse();
			EXPECT_NEAR(b.translation().z(), 0.0, 1e-9);
			return mrpt::poses::CPose2D(b.translation().x(), b.translation().y(),
										std::atan2(b.linear()(1, 0), b.linear()(0, 0)));
		};
		const mrpt::poses::CPose2D baseMotion = planarBase(frame) - planarBase(0);
		EXPECT_NEAR(odometry.x(), baseMotion.x(), 0.01);
		EXPECT_NEAR(odometry.y(), baseMotion.y(), 0.01);
		EXPECT_NEAR(odometry.phi(), baseMotion.phi(), 0.01);
		frame++;
	}
	EXPECT_EQ(frame, out.frames.size());
}
