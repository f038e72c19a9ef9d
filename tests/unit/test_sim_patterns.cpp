// Scan patterns: the rosette stays inside its circular FOV and densifies with
// integration time; a spinning sensor has exactly its beams; the grid covers
// its window at its step.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tagmap/sim/scan_pattern.h"

using namespace tagmap::sim;

namespace
{
double offAxisDeg(const Eigen::Vector3d& d) { return std::acos(std::clamp(d.x(), -1.0, 1.0)) * 180 / M_PI; }

// Fraction of 0.5-degree cells inside the FOV disc hit by rays in [0, seconds).
double rosetteCoverage(const RosettePattern& p, double seconds, double fovDeg)
{
	const double cellDeg = 0.5;
	const int n = static_cast<int>(std::ceil(fovDeg / cellDeg));
	std::set<std::pair<int, int>> hit;
	Eigen::Vector3d d;
	double dt;
	for (size_t i = 0; i < p.rayCount(seconds); i++)
	{
		p.ray(0.0, i, d, dt);
		const double ay = std::atan2(d.y(), d.x()) * 180 / M_PI, az = std::atan2(d.z(), d.x()) * 180 / M_PI;
		hit.insert({static_cast<int>(std::floor(ay / cellDeg)), static_cast<int>(std::floor(az / cellDeg))});
	}
	int inside = 0;
	for (int a = -n; a < n; a++)
		for (int b = -n; b < n; b++)
			if (std::hypot((a + 0.5) * cellDeg, (b + 0.5) * cellDeg) < 0.5 * fovDeg - cellDeg) inside++;
	int covered = 0;
	for (const auto& [a, b] : hit)
		if (std::hypot((a + 0.5) * cellDeg, (b + 0.5) * cellDeg) < 0.5 * fovDeg - cellDeg) covered++;
	return static_cast<double>(covered) / inside;
}
}  // namespace

TEST(SimPatterns, RosetteStaysInCircularFov)
{
	RosetteParams p;  // 38.4 deg, 100k pts/s
	RosettePattern pat(p);
	EXPECT_EQ(pat.rayCount(1.0), 100000u);
	double maxOff = 0;
	Eigen::Vector3d d;
	double dt;
	for (size_t i = 0; i < pat.rayCount(1.0); i++)
	{
		pat.ray(3.7, i, d, dt);
		EXPECT_NEAR(d.norm(), 1.0, 1e-12);
		maxOff = std::max(maxOff, offAxisDeg(d));
	}
	EXPECT_LE(maxOff, 19.2 + 1e-9);
	EXPECT_GT(maxOff, 19.0);  // the pattern reaches the FOV edge
	pat.ray(0.0, 50000, d, dt);
	EXPECT_DOUBLE_EQ(dt, 0.5);
}

TEST(SimPatterns, RosetteCoverageDensifiesWithTime)
{
	RosetteParams p;
	RosettePattern pat(p);
	const double c01 = rosetteCoverage(pat, 0.1, p.fovDeg);
	const double c05 = rosetteCoverage(pat, 0.5, p.fovDeg);
	const double c20 = rosetteCoverage(pat, 2.0, p.fovDeg);
	// Livox quotes ~20 % at 0.1 s and > 90 % after ~1 s (at its own resolution).
	EXPECT_LT(c01, 0.6);
	EXPECT_GT(c05, c01 + 0.1);
	EXPECT_GT(c20, 0.95);
}

TEST(SimPatterns, SpinningHasItsBeamsAndColumns)
{
	SpinningParams p;
	for (int i = 0; i < 16; i++) p.beamElevationsDeg.push_back(-15 + 2.0 * i);
	p.columns = 512;
	p.revPerSecond = 10;
	SpinningPattern pat(p);
	const size_t n = pat.rayCount(0.1);  // one revolution
	EXPECT_EQ(n, 16u * 512u);
	std::set<long> elevations, azimuths;
	Eigen::Vector3d d;
	double dt;
	for (size_t i = 0; i < n; i++)
	{
		pat.ray(0.0, i, d, dt);
		elevations.insert(std::lround(std::asin(d.z()) * 180 / M_PI * 1000));
		const double az = std::atan2(d.y(), d.x()) * 180 / M_PI;
		azimuths.insert(std::lround((az < 0 ? az + 360 : az) / (360.0 / 512)) % 512);
		EXPECT_LT(dt, 0.1);
	}
	EXPECT_EQ(elevations.size(), 16u);
	EXPECT_EQ(azimuths.size(), 512u);
	EXPECT_EQ(*elevations.begin(), -15000);
	EXPECT_EQ(*elevations.rbegin(), 15000);
}

TEST(SimPatterns, GridCoversItsWindowAtItsStep)
{
	GridParams g;
	g.azMinDeg = -10;
	g.azMaxDeg = 10;
	g.elMinDeg = -5;
	g.elMaxDeg = 5;
	g.azStepDeg = 0.5;
	g.elStepDeg = 0.25;
	GridPattern pat(g);
	EXPECT_EQ(pat.rayCount(0), 41u * 41u);
	Eigen::Vector3d d;
	double dt;
	pat.ray(0, 0, d, dt);
	EXPECT_NEAR(std::atan2(d.y(), d.x()) * 180 / M_PI, -10, 1e-9);
	EXPECT_NEAR(std::asin(d.z()) * 180 / M_PI, -5, 1e-9);
	pat.ray(0, pat.rayCount(0) - 1, d, dt);
	EXPECT_NEAR(std::atan2(d.y(), d.x()) * 180 / M_PI, 10, 1e-9);
	EXPECT_NEAR(std::asin(d.z()) * 180 / M_PI, 5, 1e-9);

	GridParams full;  // a full turn must not repeat the first column
	full.azStepDeg = 1;
	full.elMinDeg = 0;
	full.elMaxDeg = 0;
	EXPECT_EQ(GridPattern(full).rayCount(0), 360u);
}
