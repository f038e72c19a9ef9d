// Measurement physics and engineering guarantees: range noise statistics,
// footprint blending (edges, mixed pixels), exact intensity scaling,
// thread-count independence and progress reports.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tagmap/errors.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/intensity_model.h"
#include "tagmap/sim/simulate.h"

using namespace tagmap::sim;

namespace
{
// A terrestrial window onto a wall at x = 5 (and whatever `extra` adds).
Scene wallScene(double noise, int subRays, const std::string& extra = "", const std::string& step = "[0.05, 0.05]")
{
	return parseScene(
		"name: wall\n"
		"objects:\n"
		"  - {name: wall, type: plane, position: [5, 0, 0], normal: [-1, 0, 0], size: [10, 10], reflectivity: 0.5}\n" +
			extra +
			"sensors:\n"
			"  - {name: tls, type: grid, azimuth_deg: [-5, 5], elevation_deg: [-5, 5], step_deg: " +
			step + ", range_noise: " + std::to_string(noise) + ", beam: {sub_rays: " + std::to_string(subRays) +
			", divergence_mrad: 8}}\n"
			"runs:\n"
			"  - {name: s, sensor: tls, waypoints: [{position: [0, 0, 0]}]}\n",
		"wall.yaml");
}

// Same geometry, point for point; b's intensities are exactly a's x factor.
void expectSamePoints(const SimulationOutput& a, const SimulationOutput& b, double factor = 1)
{
	ASSERT_EQ(a.map.size(), b.map.size());
	for (size_t i = 0; i < a.map.size(); i++)
	{
		float ax, ay, az, bx, by, bz;
		a.map.getPointFast(i, ax, ay, az);
		b.map.getPointFast(i, bx, by, bz);
		ASSERT_EQ(ax, bx);
		ASSERT_EQ(ay, by);
		ASSERT_EQ(az, bz);
		ASSERT_EQ(b.map.getPointIntensity(i), static_cast<float>(static_cast<double>(a.map.getPointIntensity(i)) * factor));
	}
}
}  // namespace

TEST(SimPhysics, RangeNoiseIsGaussianWithSigma)
{
	const auto out = simulate(wallScene(0.02, 0), {});
	ASSERT_GT(out.map.size(), 30000u);
	double s = 0, s2 = 0;
	size_t n = 0, beyond2 = 0;
	for (const SimPoint& p : out.points)
	{
		const Eigen::Vector3f d = p.local.normalized();
		const double err = p.local.norm() - 5.0 / d.x();  // along the beam
		s += err;
		s2 += err * err;
		beyond2 += std::abs(err) > 0.04;
		n++;
	}
	const double mean = s / n, sd = std::sqrt(s2 / n - mean * mean);
	EXPECT_NEAR(mean, 0, 0.0005);
	EXPECT_NEAR(sd, 0.02, 0.0008);
	EXPECT_NEAR(static_cast<double>(beyond2) / n, 0.0455, 0.006);  // Gaussian 2-sigma tail
}

TEST(SimPhysics, IntensityScaleChangesOnlyIntensities)
{
	const Scene scene = wallScene(0.02, 4,
								  "tags:\n  - {family: tag36h11, id: 3, size: 0.4, position: [5, 0, 0], normal: [-1, 0, 0]}\n");
	SimOptions o1, o255, o65535;
	o255.intensityScale = 255;
	o65535.intensityScale = 65535;
	const auto a = simulate(scene, o1), b = simulate(scene, o255), c = simulate(scene, o65535);
	expectSamePoints(a, b, 255);
	expectSamePoints(a, c, 65535);
	float maxA = 0;
	for (size_t i = 0; i < a.map.size(); i++) maxA = std::max(maxA, a.map.getPointIntensity(i));
	EXPECT_LE(maxA, 1.0f);
	EXPECT_GT(maxA, 0.3f);  // white paper at 5 m after the residual range falloff
}

TEST(SimPhysics, SameOutputForAnyThreadCount)
{
	const Scene scene = loadScene(std::string(TAGMAP_SOURCE_DIR) + "/share/scenes/presenters.yaml");
	SimOptions o;
	o.seed = 5;
	o.threads = 1;
	const auto one = simulate(scene, o);
	o.threads = 2;
	const auto two = simulate(scene, o);
	o.threads = 5;
	const auto five = simulate(scene, o);
	expectSamePoints(one, two);
	expectSamePoints(one, five);
	o.seed = 6;
	const auto other = simulate(scene, o);
	float x1, y1, z1, x2, y2, z2;
	one.map.getPointFast(100, x1, y1, z1);
	other.map.getPointFast(100, x2, y2, z2);
	EXPECT_NE(x1, x2);  // the seed matters
}

TEST(SimPhysics, ProgressCountsEveryRayOnceAndNeverStepsBack)
{
	const Scene scene = wallScene(0.01, 0);
	SimOptions o;
	o.threads = 3;
	o.blockRays = 512;  // many blocks on few threads: reports race if unserialized
	size_t calls = 0, last = 0, lastTotal = 0;
	bool monotonic = true;
	const auto out = simulate(scene, o, [&](size_t done, size_t total) {
		calls++;  // serialized by the engine, so plain counters are safe
		monotonic = monotonic && done > last && done <= total;
		last = done;
		lastTotal = total;
	});
	EXPECT_TRUE(monotonic);
	EXPECT_EQ(last, out.raysCast);
	EXPECT_EQ(lastTotal, out.raysCast);
	EXPECT_EQ(calls, (out.raysCast + 511) / 512);
	o.blockRays = 8192;
	expectSamePoints(simulate(scene, o), simulate(scene, o, [](size_t, size_t) {}));
}

TEST(SimPhysics, FootprintBlendsIntensityAcrossInkEdges)
{
	// Thin beam: only ink or paper values; wide beam: intermediate values too.
	const std::string tag =
		"tags:\n  - {family: tag36h11, id: 0, size: 0.5, position: [5, 0, 0], normal: [-1, 0, 0]}\n";
	auto intermediateFraction = [&](int subRays) {
		Scene s = wallScene(0.0, subRays, tag, "[0.02, 0.02]");
		s.sensors[0].intensity.noiseSigma = 0;
		s.sensors[0].intensity.rangeFalloffExponent = 0;  // ink 0.06, paper 0.85 exactly
		const auto out = simulate(s, {});
		size_t onTag = 0, mid = 0;
		for (const SimPoint& p : out.points)
			if (out.objectNames[p.object] == "tag36h11:0")
			{
				onTag++;
				mid += p.intensity01 > 0.1 && p.intensity01 < 0.8;
			}
		return static_cast<double>(mid) / onTag;
	};
	EXPECT_LT(intermediateFraction(0), 0.001);
	EXPECT_GT(intermediateFraction(8), 0.03);
}

TEST(SimPhysics, DepthEdgesMakeMixedPixels)
{
	// A box 1 m in front of the wall: points floating between the two surfaces
	// appear only with a finite footprint.
	const std::string box = "  - {name: box, type: box, position: [4, 0, 0], size: [0.2, 0.6, 0.6], reflectivity: 0.5}\n";
	auto floating = [&](int subRays) {
		const auto out = simulate(wallScene(0.0, subRays, box, "[0.02, 0.02]"), {});
		size_t n = 0;
		for (const SimPoint& p : out.points)
		{
			const double x = p.local.x();
			n += x > 3.92 && x < 4.97;  // neither the box front (3.9) nor the wall (5)
		}
		return n;
	};
	EXPECT_EQ(floating(0), 0u);
	EXPECT_GT(floating(6), 50u);
}

namespace
{
// A noise-free wall with stripes `cell` wide on it; `up` turns them (z: the
// stripes run vertically, y: horizontally). `sensorExtra` adds sensor keys.
Scene stripedWall(const std::string& beam, const std::string& up, const std::string& sensorExtra = "",
				  double cell = 0.1)
{
	return parseScene(
		"name: stripes\n"
		"objects:\n"
		"  - {name: wall, type: plane, position: [5, 0, 0], normal: [-1, 0, 0], size: [10, 10], reflectivity: 0.5}\n"
		"distractors:\n"
		"  - {name: st, type: stripes, position: [4.9999, 0, 0], normal: [-1, 0, 0], up: " +
			up + ", size: [0.8, 0.8], cell: " + std::to_string(cell) +
			", dark: 0.06, light: 0.85}\n"
			"sensors:\n"
			"  - {name: tls, type: grid, azimuth_deg: [-4, 4], elevation_deg: [-4, 4], step_deg: [0.03, 0.03], "
			"range_noise: 0, beam: {" +
			beam + "}, intensity: {noise: 0, range_falloff_exponent: 0}" + sensorExtra +
			"}\n"
			"runs:\n"
			"  - {name: s, sensor: tls, waypoints: [{position: [0, 0, 0]}]}\n",
		"stripes.yaml");
}

// Fraction of the stripe sheet's points whose intensity is a blend of ink and paper.
double blendedFraction(const SimulationOutput& out)
{
	size_t on = 0, mid = 0;
	for (const SimPoint& p : out.points)
		if (out.objectNames[p.object] == "st")
		{
			on++;
			mid += p.intensity01 > 0.1 && p.intensity01 < 0.8;
		}
	return on ? static_cast<double>(mid) / on : 0;
}
}  // namespace

TEST(SimPhysics, EllipticalBeamBlendsOnlyAcrossItsLongAxis)
{
	// 0.5 x 16 mrad at 5 m: 1.5 mm wide, 48 mm tall. Vertical stripes (edges
	// vertical) are crossed by the narrow axis, horizontal ones by the long one.
	const std::string ellipse = "divergence_mrad: [0.5, 16], sub_rays: 8";
	const double acrossNarrow = blendedFraction(simulate(stripedWall(ellipse, "[0, 0, 1]"), {}));
	const double acrossLong = blendedFraction(simulate(stripedWall(ellipse, "[0, 1, 0]"), {}));
	EXPECT_LT(acrossNarrow, 0.03);
	EXPECT_GT(acrossLong, 0.3);
	// The scalar still means a circle: both orientations alike.
	const std::string circle = "divergence_mrad: 8, sub_rays: 8";
	const double v = blendedFraction(simulate(stripedWall(circle, "[0, 0, 1]"), {}));
	const double h = blendedFraction(simulate(stripedWall(circle, "[0, 1, 0]"), {}));
	EXPECT_GT(v, 0.1);
	EXPECT_NEAR(v, h, 0.05);
}

TEST(SimPhysics, DivergenceScalarIsCircularPairIsElliptical)
{
	const Scene circle = stripedWall("divergence_mrad: 2", "[0, 0, 1]");
	EXPECT_EQ(circle.sensors[0].beam.divergenceMrad, 2);
	EXPECT_EQ(circle.sensors[0].beam.divergenceVerticalMrad, 2);
	EXPECT_TRUE(circle.sensors[0].beam.circular());
	const Scene ellipse = stripedWall("divergence_mrad: [0.5, 4.9]", "[0, 0, 1]");
	EXPECT_EQ(ellipse.sensors[0].beam.divergenceMrad, 0.5);
	EXPECT_EQ(ellipse.sensors[0].beam.divergenceVerticalMrad, 4.9);
	EXPECT_FALSE(ellipse.sensors[0].beam.circular());
	EXPECT_THROW(stripedWall("divergence_mrad: [0.5]", "[0, 0, 1]"), tagmap::InputError);
}

TEST(SimPhysics, PointingJitterMovesTheBeamNotTheReportedDirection)
{
	// Thin beam, no noise: every difference from the jitter-free map comes
	// from the jitter. Points stay on their reported rays; their intensities
	// come from where the beam really went (the incidence changes a little
	// for every point; ink for paper only near an edge): a point within about 0.4 sigma x
	// range of an edge (expected 2 x 0.4 sigma r / cell of them) reads the
	// other stripe.
	const auto base = simulate(stripedWall("sub_rays: 0", "[0, 0, 1]", "", 0.05), {});
	auto changed = [&](double mrad) {
		const auto j = simulate(
			stripedWall("sub_rays: 0, pointing_jitter_mrad: " + std::to_string(mrad), "[0, 0, 1]", "", 0.05), {});
		EXPECT_EQ(j.points.size(), base.points.size());
		size_t n = 0;
		for (size_t i = 0; i < j.points.size() && i < base.points.size(); i++)
		{
			EXPECT_LT((j.points[i].local.normalized() - base.points[i].local.normalized()).norm(), 1e-5);
			n += std::abs(j.points[i].intensity01 - base.points[i].intensity01) > 0.3f;  // ink <-> paper
		}
		return static_cast<double>(n) / j.points.size();
	};
	EXPECT_EQ(changed(0), 0.0);
	const double small = changed(1), large = changed(4);
	EXPECT_NEAR(small, 0.08, 0.03);  // 1 mrad: 5 mm at 5 m on 5 cm stripes
	EXPECT_GT(large, 2.5 * small);
	EXPECT_LT(large, 0.45);
}

TEST(SimPhysics, RangeWalkPutsDarkInkBehindWhitePaper)
{
	// Falloff off, gain 1: amplitudes are the reflectivities 0.06 and 0.85,
	// so ink reads walk x (0.85 - 0.06) farther than paper.
	auto inkBehindPaper = [](double walk) {
		const auto out = simulate(stripedWall("sub_rays: 0", "[0, 0, 1]", ", range_walk: " + std::to_string(walk)), {});
		double ink = 0, paper = 0;
		size_t ni = 0, np = 0;
		for (const SimPoint& p : out.points)
		{
			if (out.objectNames[p.object] != "st") continue;
			const double along = p.local.norm();
			const double r = 4.9999 * along / p.local.x();  // true range along the ray
			if (p.intensity01 < 0.1)
				ink += along - r, ni++;
			else
				paper += along - r, np++;
		}
		EXPECT_GT(ni, 1000u);
		EXPECT_GT(np, 1000u);
		return ink / ni - paper / np;
	};
	EXPECT_NEAR(inkBehindPaper(0), 0, 1e-5);
	EXPECT_NEAR(inkBehindPaper(0.004), 0.004 * (0.85 - 0.06), 5e-5);
}

TEST(SimPhysics, SaturationClipsAndBitsQuantize)
{
	// Paper 0.85 saturates at 0.5 (reads full scale); ink 0.06 reads 0.12.
	auto run = [&](const std::string& bits) {
		Scene s = stripedWall("sub_rays: 0", "[0, 0, 1]");
		s.sensors[0].intensity.saturation = 0.5;
		s.sensors[0].intensity.noiseSigma = 0.01;
		if (!bits.empty()) s.sensors[0].intensity.bits = std::stoi(bits);
		return simulate(s, {});
	};
	const auto cont = run("");
	size_t full = 0, paper = 0;
	for (const SimPoint& p : cont.points)
		if (cont.objectNames[p.object] == "st" && p.intensity01 > 0.5)
		{
			paper++;
			full += p.intensity01 == 1.0f;
		}
	EXPECT_GT(paper, 1000u);
	EXPECT_EQ(full, paper);  // 0.85 + noise never falls below 0.5
	for (int bits : {8, 16})
	{
		const auto q = run(std::to_string(bits));
		const double levels = (1u << bits) - 1;
		std::set<float> distinct;
		for (const SimPoint& p : q.points)
		{
			const double level = p.intensity01 * levels;
			ASSERT_NEAR(level, std::round(level), 1e-6 * levels) << bits;
			distinct.insert(p.intensity01);
		}
		if (bits == 8)
		{
			EXPECT_LT(distinct.size(), 257u);
		}
		else
		{
			EXPECT_GT(distinct.size(), 256u);  // noise 0.01 spans ~1300 levels
		}
	}
	const Scene parsed = parseScene(
		"name: q\nobjects: []\nsensors:\n  - {name: s, type: spinning, intensity: {saturation: 0.5, bits: 16}}\n"
		"runs:\n  - {name: r, sensor: s, duration: 0.1, waypoints: [{position: [0, 0, 0]}]}\n",
		"q.yaml");
	EXPECT_EQ(parsed.sensors[0].intensity.bits, 16);
	EXPECT_EQ(parsed.sensors[0].intensity.saturation, 0.5);
	EXPECT_THROW(parseScene("name: q\nobjects: []\nsensors:\n  - {name: s, type: spinning, intensity: {bits: 12}}\n"
							"runs:\n  - {name: r, sensor: s, duration: 0.1, waypoints: [{position: [0, 0, 0]}]}\n",
							"q.yaml"),
				 tagmap::InputError);
}

TEST(SimPhysics, DetectionRangeFollowsReceivedPowerNotTheReportedFalloff)
{
	// A MID-40-like receiver (10 % reflectivity returns to 90 m): 2 % ink
	// returns to 90 * sqrt(0.2) = 40.2 m whatever the reported intensity's
	// residual falloff; the legacy threshold applies that falloff, and at
	// range^2 loses the same ink beyond 2.6 m.
	IntensityParams legacy;
	legacy.rangeFalloffExponent = 2;
	IntensityParams power = legacy;
	power.detectionRange10 = 90;
	const IntensityModel a(legacy), b(power);
	const double ink = a.returnStrength(0.02, 1.0);
	EXPECT_TRUE(a.detected(ink, 2.5));
	EXPECT_FALSE(a.detected(ink, 2.7));
	EXPECT_TRUE(b.detected(ink, 40.0));
	EXPECT_FALSE(b.detected(ink, 40.5));
	EXPECT_FALSE(b.detected(0.0, 1.0));  // no echo is never detected
	Rng r1(7), r2(7);
	EXPECT_EQ(a.intensity(ink, 10.0, r1), b.intensity(ink, 10.0, r2));  // what it reports is unchanged
	const Scene parsed = parseScene(
		"name: q\nobjects: []\nsensors:\n  - {name: s, type: livox_mid40, intensity: {detection_range_10pct: 90}}\n"
		"runs:\n  - {name: r, sensor: s, duration: 0.1, waypoints: [{position: [0, 0, 0]}]}\n",
		"q.yaml");
	EXPECT_EQ(parsed.sensors[0].intensity.detectionRange10, 90);
}
