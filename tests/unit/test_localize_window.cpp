// window_disagreement.h: how much the scans of a merged window disagree about
// a tag, on synthetic scans of a printed tag36h11 placed with known offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tagmap/localize/window_disagreement.h"
#include "tagmap/tag_family.h"

using namespace tagmap;
using namespace tagmap::localize;

namespace
{
// A 0.6 m tag36h11 (id 3) 4 m ahead of the sensor, facing it.
TagDetection tagAhead()
{
	TagDetection t;
	t.family = "tag36h11";
	t.id = 3;
	t.size = 0.6;
	t.pose.linear() << 0, 0, -1, 1, 0, 0, 0, -1, 0;  // tag z towards the sensor (-x)
	t.pose.translation() = Eigen::Vector3d(4, 0, 0);
	return t;
}

struct Offset
{
	double x = 0, y = 0, normal = 0;  // metres, in the tag's frame
	double xFrom = -0.5, xTo = 0.5;  // the part of the grid's width the scan covers (a petal's share)
};

// One scan per offset: `points` on the tag's grid with the bitmap's
// intensity (white paper beyond it) and Gaussian range noise, shifted by the
// offset as a misplaced scan would be; as many again on the wall around.
mrpt::maps::CPointsMapXYZI scansOf(const TagDetection& t, const std::vector<Offset>& offsets, size_t points,
								   double noise, std::vector<size_t>& starts)
{
	const TagBitmap bm = renderTagBitmap(t.family, t.id);
	const double cell = t.size / bm.borderCells, toCentre = bm.borderStart + bm.borderCells / 2.0;
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> u(-0.5, 0.5);
	std::normal_distribution<double> g(0, noise), gi(0, 0.02);
	mrpt::maps::CPointsMapXYZI m;
	starts.clear();
	for (const Offset& off : offsets)
	{
		starts.push_back(m.size());
		for (size_t i = 0; i < 2 * points; i++)
		{
			const double extent = (i < points ? 1.0 : 3.0) * bm.cells * cell;
			const double x = i < points ? extent * (off.xFrom + (off.xTo - off.xFrom) * (u(rng) + 0.5)) : extent * u(rng);
			const double y = extent * u(rng);
			const int col = static_cast<int>(std::floor(x / cell + toCentre));
			const int row = static_cast<int>(std::floor(-y / cell + toCentre));
			const bool onGrid = col >= 0 && row >= 0 && col < bm.cells && row < bm.cells;
			const double white = onGrid ? bm.at(row, col) / 255.0 : 1.0;
			const Eigen::Vector3d p = t.pose * Eigen::Vector3d(x + off.x, y + off.y, off.normal + g(rng));
			m.insertPointFast(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
			m.setPointIntensity(m.size() - 1, static_cast<float>(0.1 + 0.7 * white + gi(rng)));
		}
	}
	return m;
}
}  // namespace

TEST(WindowDisagreement, ScansPlacedOffAlongTheNormal)
{
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	// Offsets 0, +1 cm, -1 cm: a spread (sample standard deviation) of 1 cm.
	const auto m = scansOf(t, {{0, 0, 0}, {0, 0, 0.01}, {0, 0, -0.01}}, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	EXPECT_EQ(w.scansCompared, 3);
	// The merged tag drifts from the current scan by the mean of the older
	// scans' random-walk offsets: 5/6 of their spread's variance at 3 scans.
	EXPECT_NEAR(w.alongNormal, 0.01 * std::sqrt(5.0 / 6), 0.0015);
	EXPECT_LT(w.inPlaneX, 0.002);
	EXPECT_LT(w.inPlaneY, 0.002);
	// Each scan covers the whole tag: its offset moves the plane, not its tilt.
	EXPECT_LT(std::sqrt(w.rotation(0, 0)), 0.003);
	EXPECT_LT(std::sqrt(w.rotation(1, 1)), 0.003);
}

TEST(WindowDisagreement, AlongWindowsMergedTagDriftsMoreThanItsScansSpread)
{
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	std::vector<Offset> offsets;
	for (int s = 0; s < 10; s++) offsets.push_back({0, 0, s % 2 ? 0.01 : -0.01});
	const auto m = scansOf(t, offsets, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	// Spread sqrt(10 / 9) cm; the merged mean of a 10-scan random walk has
	// 6 / 11 * sum over j of (j / 10)^2 = 1.5545 times that variance.
	EXPECT_NEAR(w.alongNormal, 0.01 * std::sqrt(10.0 / 9 * 6.0 / 11 * 2.85), 0.0015);
}

TEST(WindowDisagreement, ScansOnDifferentHalvesTiltTheTag)
{
	// A rosette's petals: one scan on the tag's left half, one on its right,
	// 2 cm apart along the normal. The plane through both tilts about the
	// tag's y by 2 cm over the halves' 0.45 m: 0.044 rad.
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {{0, 0, 0.01, -0.5, 0}, {0, 0, -0.01, 0, 0.5}}, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	// Two readings 2 cm apart spread by 1.41 cm; a plane fitted to two
	// halves of the 0.9 m grid (quiet zone included) moved by that much
	// turns by 1.41 cm * sqrt(4.5) / 0.9 m = 0.033 rad (std).
	EXPECT_NEAR(std::sqrt(w.rotation(1, 1)), 0.033, 0.006);
	EXPECT_LT(std::sqrt(w.rotation(0, 0)), 0.005);  // both halves span the tag's height
	EXPECT_LT(std::sqrt(w.rotation(2, 2)), 0.005);  // no shift in the plane
}

TEST(WindowDisagreement, ScansOnDifferentHalvesShiftedAlongTheTagTurnIt)
{
	// The same halves shifted 2 cm apart along the tag's y: the pattern
	// fitted to both turns about the normal. Readings spread 1.41 cm; a
	// rigid fit of two halves of the 0.9 m grid turns by 1.41 cm *
	// sqrt(1.125) / 0.9 m = 0.017 rad (std).
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {{0, 0.01, 0, -0.5, 0}, {0, -0.01, 0, 0, 0.5}}, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	EXPECT_NEAR(std::sqrt(w.rotation(2, 2)), 0.017, 0.004);
	EXPECT_LT(std::sqrt(w.rotation(0, 0)), 0.005);
	EXPECT_LT(std::sqrt(w.rotation(1, 1)), 0.005);
}

TEST(WindowDisagreement, ScansPlacedOffInThePlane)
{
	// The drift of a sensor looking sideways as it drives: along the tag.
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {{0, 0, 0}, {0.015, 0, 0}, {-0.015, 0, 0}}, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	EXPECT_NEAR(w.inPlaneX, 0.015 * std::sqrt(5.0 / 6), 0.003);
	EXPECT_LT(w.inPlaneY, 0.003);
	EXPECT_LT(w.alongNormal, 0.0015);
}

TEST(WindowDisagreement, ScansThatLineUpAddNothingButNoise)
{
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {{}, {}, {}, {}}, 1500, 0.02, starts);  // 2 cm range noise, as a Livox
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.02);
	EXPECT_EQ(w.scansCompared, 4);
	EXPECT_LT(w.alongNormal, 0.0015);
	EXPECT_LT(w.inPlaneX, 0.003);
	EXPECT_LT(w.inPlaneY, 0.003);
	// One scan alone, or none on the tag: nothing to compare.
	EXPECT_EQ(windowMisregistration(t, m, {0}, 0.02).alongNormal, 0);
	TagDetection far = t;
	far.pose.translation() = Eigen::Vector3d(40, 0, 0);
	EXPECT_EQ(windowMisregistration(far, m, starts, 0.02).scansCompared, 0);
}

TEST(WindowDisagreement, MisregistrationIsAddedInTheTagsFrame)
{
	TagDetection t = tagAhead();  // tag x = sensor y, tag y = sensor -z, tag z = sensor -x
	t.covariance.diagonal() << 1e-6, 1e-6, 1e-6, 1e-4, 1e-4, 1e-4;
	WindowMisregistration w;
	w.inPlaneX = 0.01;
	w.alongNormal = 0.02;
	addMisregistration(t, w);
	EXPECT_NEAR(t.covariance(1, 1), 1e-6 + 1e-4, 1e-12);  // sensor y: the tag's x
	EXPECT_NEAR(t.covariance(0, 0), 1e-6 + 4e-4, 1e-12);  // sensor x: the normal
	EXPECT_NEAR(t.covariance(2, 2), 1e-6, 1e-12);
	EXPECT_EQ(t.covariance(3, 3), 1e-4);  // no turn given: the orientation as it was
	EXPECT_EQ(t.covariance(0, 1), 0);
	w = {};
	w.rotation(1, 1) = 4e-4;  // about the tag's y = the sensor's -z
	addMisregistration(t, w);
	EXPECT_NEAR(t.covariance(5, 5), 1e-4 + 4e-4, 1e-12);
	EXPECT_NEAR(t.covariance(3, 3), 1e-4, 1e-12);
}
