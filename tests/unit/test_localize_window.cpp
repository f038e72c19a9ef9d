// window_disagreement.h: how much the scans of a merged window disagree about
// a tag, measured on synthetic scans of one tag with known offsets.
#include <gtest/gtest.h>

#include <random>

#include "tagmap/localize/window_disagreement.h"

using namespace tagmap;
using namespace tagmap::localize;

namespace
{
// A 0.6 m tag 4 m ahead of the sensor, facing it.
TagDetection tagAhead()
{
	TagDetection t;
	t.family = "tag36h11";
	t.size = 0.6;
	t.pose.linear() << 0, 0, -1, 1, 0, 0, 0, -1, 0;  // tag z towards the sensor (-x)
	t.pose.translation() = Eigen::Vector3d(4, 0, 0);
	return t;
}

// Scans of `points` each on the tag and around it, shifted along the tag's
// normal by `offsets` (metres), with Gaussian range noise `noise`; also
// `points` on the wall beyond the tag's square, which must not count.
mrpt::maps::CPointsMapXYZI scansOf(const TagDetection& t, const std::vector<double>& offsets, size_t points,
								   double noise, std::vector<size_t>& starts)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> u(-0.5, 0.5);
	std::normal_distribution<double> g(0, noise);
	mrpt::maps::CPointsMapXYZI m;
	starts.clear();
	for (double off : offsets)
	{
		starts.push_back(m.size());
		for (size_t i = 0; i < 2 * points; i++)
		{
			const double spread = i < points ? t.size : 3 * t.size;  // the second half mostly off the tag
			const Eigen::Vector3d p = t.pose * Eigen::Vector3d(spread * u(rng), spread * u(rng), off + g(rng));
			m.insertPointFast(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
		}
	}
	return m;
}
}  // namespace

TEST(WindowDisagreement, ScansPlacedOffByOdometryShowTheirSpread)
{
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	// Offsets 0, +1 cm, -1 cm: a points-weighted RMS of 0.816 cm.
	const auto m = scansOf(t, {0, 0.01, -0.01}, 400, 0.005, starts);
	EXPECT_NEAR(windowMisregistration(t, m, starts, 0.005), 0.00816, 0.0015);
}

TEST(WindowDisagreement, ScansThatLineUpAddNothingButNoise)
{
	const TagDetection t = tagAhead();
	std::vector<size_t> starts;
	const auto m = scansOf(t, {0, 0, 0, 0}, 400, 0.02, starts);  // 2 cm range noise, as a Livox
	EXPECT_LT(windowMisregistration(t, m, starts, 0.02), 0.0015);
	// One scan alone, or none on the tag: nothing to compare.
	EXPECT_EQ(windowMisregistration(t, m, {0}, 0.02), 0);
	TagDetection far = t;
	far.pose.translation() = Eigen::Vector3d(40, 0, 0);
	EXPECT_EQ(windowMisregistration(far, m, starts, 0.02), 0);
}

TEST(WindowDisagreement, PositionVarianceGrowsByTheSquare)
{
	TagDetection t = tagAhead();
	t.covariance.diagonal() << 1e-6, 1e-6, 1e-6, 1e-4, 1e-4, 1e-4;
	addPositionUncertainty(t, 0.01);
	EXPECT_NEAR(t.covariance(0, 0), 1e-6 + 1e-4, 1e-12);
	EXPECT_NEAR(t.covariance(2, 2), 1e-6 + 1e-4, 1e-12);
	EXPECT_EQ(t.covariance(3, 3), 1e-4);
	EXPECT_EQ(t.covariance(0, 1), 0);
}
