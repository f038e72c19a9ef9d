// SLAM-like drift: zero at the start, a random walk whose spread matches the
// configured rate, and visible in the merged map while the per-frame clouds
// stay exact.
#include <gtest/gtest.h>

#include <cmath>

#include "tagmap/sim/drift.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/simulate.h"

using namespace tagmap::sim;

namespace
{
std::vector<DriftStep> straightLine(double length, int n)
{
	std::vector<DriftStep> steps(n + 1);
	for (int k = 0; k <= n; k++)
	{
		steps[k].truePose = Eigen::Isometry3d::Identity();
		steps[k].truePose.translation() = Eigen::Vector3d(length * k / n, 0, 0);
		steps[k].seconds = k ? 0.1 : 0;
	}
	return steps;
}
}  // namespace

TEST(SimDrift, RandomWalkSpreadMatchesRate)
{
	DriftParams p;
	p.translationPerSqrtM = 0.01;
	p.rotationDegPerSqrtM = 0;
	p.translationPerSqrtS = 0;
	p.rotationDegPerSqrtS = 0;
	const double length = 25;
	const auto steps = straightLine(length, 250);
	double s2 = 0;
	const int trials = 400;
	for (int seed = 0; seed < trials; seed++)
	{
		const auto d = driftPoses(steps, p, seed);
		EXPECT_TRUE(d.front().isApprox(steps.front().truePose));
		s2 += (d.back().translation() - steps.back().truePose.translation()).squaredNorm();
	}
	// Per axis variance = rate^2 * distance; three axes.
	const double rms = std::sqrt(s2 / trials);
	const double expected = p.translationPerSqrtM * std::sqrt(3 * length);
	EXPECT_NEAR(rms, expected, 0.1 * expected);
}

TEST(SimDrift, ScaleMultipliesDrift)
{
	DriftParams p;
	auto steps = straightLine(10, 100);
	const auto d1 = driftPoses(steps, p, 3);
	for (auto& s : steps) s.scale = 3;
	const auto d3 = driftPoses(steps, p, 3);
	const double e1 = (d1.back().translation() - steps.back().truePose.translation()).norm();
	const double e3 = (d3.back().translation() - steps.back().truePose.translation()).norm();
	EXPECT_GT(e3, 2 * e1);  // same noise draws, three times the step sigma (rotation makes it not exactly 3x)
}

TEST(SimDrift, SystematicOdometryErrorActsOnTheCarrier)
{
	// No random drift: 10 m straight in 1 m steps by a base carrying its
	// sensor 0.5 m ahead, turned 90 deg. The base's odometry (drifted sensor
	// pose * mount^-1) must read every step 2 % long and turned 1 deg.
	DriftParams p;
	p.translationPerSqrtM = p.rotationDegPerSqrtM = p.translationPerSqrtS = p.rotationDegPerSqrtS = 0;
	Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
	mount.translation() = Eigen::Vector3d(0.5, 0, 1);
	mount.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	auto steps = straightLine(10, 10);
	for (auto& s : steps)
	{
		s.truePose = s.truePose * mount;
		s.mount = mount;
		s.scaleError = 0.02;
		s.headingBiasRadPerM = M_PI / 180;
	}
	const auto d = driftPoses(steps, p, 1);
	for (size_t k = 1; k < d.size(); k++)
	{
		const Eigen::Isometry3d move = (d[k - 1] * mount.inverse()).inverse() * (d[k] * mount.inverse());
		EXPECT_NEAR(move.translation().norm(), 1.02, 1e-9) << "step " << k;
		EXPECT_NEAR(Eigen::AngleAxisd(move.linear()).angle(), M_PI / 180, 1e-9) << "step " << k;
	}
	// Without the errors the poses are the true ones, exactly.
	for (auto& s : steps) s.scaleError = s.headingBiasRadPerM = 0;
	const auto exact = driftPoses(steps, p, 1);
	for (size_t k = 0; k < exact.size(); k++) EXPECT_TRUE(exact[k].isApprox(steps[k].truePose, 1e-12));
}

TEST(SimDrift, MergedMapUsesDriftedPosesAndFramesStayExact)
{
	const Scene scene = parseScene(
		"name: corridor\n"
		"drift: {translation_per_sqrt_m: 0.02, rotation_deg_per_sqrt_m: 0.2}\n"
		"objects:\n"
		"  - {name: end, type: plane, position: [20, 0, 1], normal: [-1, 0, 0], size: [10, 6], reflectivity: 0.5}\n"
		"sensors:\n"
		"  - {name: l, type: livox_mid40, range_noise: 0}\n"
		"runs:\n"
		"  - {name: walk, sensor: l, waypoints: [{t: 0, position: [0, 0, 1]}, {t: 10, position: [10, 0, 1]}]}\n",
		"corridor.yaml");
	const auto out = simulate(scene, {});
	ASSERT_EQ(out.frames.size(), 100u);
	EXPECT_TRUE(out.frames.front().driftedPose.isApprox(out.frames.front().truePose));
	const double finalError =
		(out.frames.back().driftedPose.translation() - out.frames.back().truePose.translation()).norm();
	EXPECT_GT(finalError, 0.005);
	EXPECT_LT(finalError, 0.5);
	// Frame-local points at the TRUE pose land on the wall (up to the beam
	// footprint's range averaging); in the map they sit at the drifted pose.
	const FrameData& f = out.frames.back();
	double worstTrue = 0, minShift = 1e9;
	for (size_t i = f.firstPoint; i < f.firstPoint + f.pointCount; i++)
	{
		const Eigen::Vector3d g = f.truePose * out.points[i].local.cast<double>();
		worstTrue = std::max(worstTrue, std::abs(g.x() - 20));
		float x, y, z;
		out.map.getPointFast(i, x, y, z);
		minShift = std::min(minShift, (Eigen::Vector3d(x, y, z) - g).norm());
	}
	EXPECT_LT(worstTrue, 0.005);
	EXPECT_GT(minShift, 0.002);
}
