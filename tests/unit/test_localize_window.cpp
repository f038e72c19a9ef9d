// window_disagreement.h: how much the scans of a merged window disagree about
// a tag, on synthetic scans of a printed tag36h11 placed with known offsets.
#include <gtest/gtest.h>

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
			const double x = extent * u(rng), y = extent * u(rng);
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
	EXPECT_NEAR(w.alongNormal, 0.01, 0.0015);
	EXPECT_LT(w.inPlaneX, 0.002);
	EXPECT_LT(w.inPlaneY, 0.002);
}

TEST(WindowDisagreement, ScansPlacedOffInThePlane)
{
	// The drift of a sensor looking sideways as it drives: along the tag.
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {{0, 0, 0}, {0.015, 0, 0}, {-0.015, 0, 0}}, 1500, 0.005, starts);
	const WindowMisregistration w = windowMisregistration(t, m, starts, 0.005);
	EXPECT_NEAR(w.inPlaneX, 0.015, 0.003);
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
	EXPECT_EQ(t.covariance(3, 3), 1e-4);  // the orientation as it was
	EXPECT_EQ(t.covariance(0, 1), 0);
}
