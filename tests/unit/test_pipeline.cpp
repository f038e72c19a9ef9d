#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "synthetic_wall.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/pipeline.h"
#include "tagmap/point_spacing.h"
#include "tagmap/quantile.h"
#include "tagmap/tag_pose.h"

using namespace tagmap;
using tagmap::testing::makeWall;
using tagmap::testing::WallScene;

namespace
{
double maxCornerError(const TagDetection& a, const TagDetection& b)
{
	double e = 0;
	for (int k = 0; k < 4; k++) e = std::max(e, (a.corners[k] - b.corners[k]).norm());
	return e;
}

Eigen::Isometry3d wallPose(double yaw, double pitch, const Eigen::Vector3d& t)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()))
					 .toRotationMatrix();
	T.translation() = t;
	return T;
}

// Detects `s`'s wall with `p` and expects its one tag, and nothing else;
// prints the counts of `stage` and of cluster_split, which finds it.
void expectOnlyTheWallsTag(const WallScene& s, const PipelineParams& p, const std::string& stage)
{
	TagDetection truth;
	const Detections found = Pipeline(p).detect(makeWall(s, truth));
	for (const StageReport& st : found.stages)
		if (st.name == stage || st.name == "cluster_split")
			std::printf("%s: %zu in, %zu out\n", st.name.c_str(), st.itemsIn, st.itemsOut);
	ASSERT_EQ(found.tags.size(), 1u);
	EXPECT_EQ(found.tags[0].family, s.family);
	EXPECT_EQ(found.tags[0].id, s.id);
	EXPECT_LT(maxCornerError(found.tags[0], truth), 0.01);
}
}  // namespace

TEST(PointSpacing, MatchesGridSpacing)
{
	WallScene s;
	TagDetection truth;
	const auto map = makeWall(s, truth);
	const double sp = estimatePointSpacing(map.getPointsBufferRef_x().data(), map.getPointsBufferRef_y().data(),
										   map.getPointsBufferRef_z().data(), map.size());
	EXPECT_GT(sp, 0.4 * s.spacing);
	EXPECT_LT(sp, 1.2 * s.spacing);
}

// The spacing is exact: the median over the evenly strided samples of each
// one's nearest other point among all points, whichever way the points are
// bucketed (every point's own cell for few points, the samples' blocks for
// many).
TEST(PointSpacing, IsTheSamplesExactMedianNearestDistanceForFewAndManyPoints)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<float> along(0, 2), noise(-0.004f, 0.004f);
	std::vector<float> xs, ys, zs;
	for (int i = 0; i < 3000; i++)
	{
		// Two walls at right angles, unevenly sampled, with range noise.
		const float a = along(rng), b = along(rng);
		const bool first = i % 2 == 0;
		xs.push_back(first ? a : noise(rng));
		ys.push_back(first ? noise(rng) : a);
		zs.push_back(b);
	}
	const size_t n = xs.size();
	for (const size_t samples : {200, 100})  // 3000 points: below 27 x 200, above 27 x 100
	{
		const size_t stride = n / samples;
		std::vector<double> nearest;
		for (size_t i = stride / 2; i < n; i += stride)
		{
			double best = std::numeric_limits<double>::max();
			for (size_t j = 0; j < n; j++)
			{
				const double d = std::hypot(xs[j] - xs[i], ys[j] - ys[i], zs[j] - zs[i]);
				if (j != i && d > 0) best = std::min(best, d);
			}
			nearest.push_back(best);
		}
		PointSpacingParams p;
		p.samples = samples;
		EXPECT_EQ(estimatePointSpacing(xs.data(), ys.data(), zs.data(), n, p, 1), medianInPlace(nearest)) << samples;
	}
}

TEST(Pipeline, FindsTagOnWallInAnyOrientation)
{
	// A wall, a ceiling, a floor and a tilted board: the published code only
	// handled normals along z; every orientation must work.
	const Eigen::Isometry3d poses[] = {
		wallPose(0.3, M_PI / 2, Eigen::Vector3d(3, 1, 1)),  // vertical wall
		wallPose(0.2, M_PI, Eigen::Vector3d(0, 0, 3)),  // ceiling, facing down
		wallPose(-1.0, 0.0, Eigen::Vector3d(1, -2, 0)),  // floor, facing up
		wallPose(2.0, 0.7, Eigen::Vector3d(-4, 2, 1.5)),  // tilted board
	};
	for (const auto& T : poses)
	{
		WallScene s;
		s.T_G_wall = T;
		s.tagRotation = 0.4;
		TagDetection truth;
		const auto map = makeWall(s, truth);
		const Detections found = Pipeline().detect(map);
		ASSERT_EQ(found.tags.size(), 1u) << T.matrix();
		EXPECT_EQ(found.tags[0].family, "tag36h11");
		EXPECT_EQ(found.tags[0].id, 7);
		EXPECT_LT(maxCornerError(found.tags[0], truth), 0.004) << T.matrix();
		EXPECT_NEAR(found.tags[0].size, s.size, 0.004);
	}
}

TEST(Pipeline, ATagIsDecodedOnceFromItsLargestClusterAndItsOtherBoxesNameIt)
{
	// The clusterings at two tolerances and the density levels propose
	// several boxes around one tag: the one of the most cluster points is
	// decoded, the others centred on its tag are not (decode_schedule.h).
	WallScene s;
	s.T_G_wall = wallPose(0.3, M_PI / 2, Eigen::Vector3d(3, 1, 1));
	TagDetection truth;
	const Detections found = Pipeline().detect(makeWall(s, truth));
	ASSERT_EQ(found.tags.size(), 1u);
	size_t decoded = 0, spared = 0;
	for (const CandidateReport& c : found.candidates)
	{
		decoded += c.verdict == Verdict::Decoded;
		if (c.verdict != Verdict::OnDecodedTag) continue;
		spared++;
		ASSERT_TRUE(c.onTagOf.has_value());
		const CandidateReport& by = found.candidates.at(*c.onTagOf);
		EXPECT_EQ(by.verdict, Verdict::Decoded);
		EXPECT_LE(c.clusterPoints, by.clusterPoints);
		EXPECT_LT((c.center - found.tags[0].position()).norm(), 0.5 * found.tags[0].size);
	}
	EXPECT_EQ(decoded, 1u);
	EXPECT_GE(spared, 1u);
}

TEST(IntermediatePlane, SeenFromBehindKeepsIdAndVertexOrder)
{
	// The box of a cluster has no preferred side: render the tag's plane
	// from the front and from behind (box normal flipped). The second image
	// is mirrored; the mirrored decode must give the same id and the same
	// physical corners, in vertex order.
	WallScene s;
	s.family = "aruco_4x4_50";
	s.id = 1;
	s.T_G_wall = wallPose(0.3, M_PI / 2, Eigen::Vector3d(2, 0, 1));
	TagDetection truth;
	const auto map = makeWall(s, truth);
	const float *xs = map.getPointsBufferRef_x().data(), *ys = map.getPointsBufferRef_y().data(),
				*zs = map.getPointsBufferRef_z().data(), *is = map.getPointsBufferRef_intensity().data();
	std::vector<uint32_t> all(map.size());
	for (uint32_t i = 0; i < all.size(); i++) all[i] = i;
	TagDecoder decoder({"aruco_4x4_50"});
	for (bool fromBehind : {false, true})
	{
		OrientedBox box;
		box.center = truth.position();
		box.axes = truth.pose.linear();
		box.extent = Eigen::Vector3d(0.3, 0.3, 0.01);
		if (fromBehind) box.axes.col(2) *= -1, box.axes.col(1) *= -1;
		const PlaneImage plane = renderIntermediatePlane(xs, ys, zs, is, all, box, s.spacing, IntermediatePlaneParams{});
		const auto decoded = decoder.decode(plane.gray);
		ASSERT_EQ(decoded.size(), 1u);
		EXPECT_EQ(decoded[0].id, 1);  // not 256: the published ArUco code's mirror bug
		EXPECT_EQ(decoded[0].mirrored, fromBehind);
		const TagDetection t = solveTagPose(decoded[0], plane, 0);
		EXPECT_LT(maxCornerError(t, truth), 0.005);
		EXPECT_GT(t.pose.linear().col(2).dot(truth.pose.linear().col(2)), 0.999);
	}
}

TEST(Pipeline, IntensityScaleDoesNotChangeTheResult)
{
	WallScene s;
	s.T_G_wall = wallPose(0.5, M_PI / 2, Eigen::Vector3d(2, 2, 1));
	TagDetection truth;
	std::vector<TagDetection> results;
	for (double scale : {1.0, 255.0, 65535.0})
	{
		s.intensityScale = scale;
		const Detections found = Pipeline().detect(makeWall(s, truth));
		ASSERT_EQ(found.tags.size(), 1u) << scale;
		results.push_back(found.tags[0]);
	}
	for (size_t k = 1; k < results.size(); k++)
	{
		EXPECT_EQ(results[k].id, results[0].id);
		EXPECT_LT(maxCornerError(results[k], results[0]), 1e-5);
	}
}

// Range noise thicker than the gradient's radius and strong intensity
// noise: the wall's noise passes the gradient's fixed bars here and there
// and clusters with the tag into one box too large for the size asked for.
// Without the points chance explains, the tag's edges stand apart.
TEST(Pipeline, TagOnAWallNoisierThanTheRadiusIsFound)
{
	WallScene s;
	s.spacing = 0.004;
	s.noise = 0.015;
	s.intensityNoise = 0.12;
	s.wall = 1.2;
	s.T_G_wall = wallPose(0.3, M_PI / 2, Eigen::Vector3d(3, 1, 1));
	PipelineParams p;
	p.tagSize = s.size;
	expectOnlyTheWallsTag(s, p, "intensity_gradient");
}

// A wall whose intensity stripes (scan lines at different ranges) clear the
// gradient's bar all over clusters whole with the tag on it, into a box
// wider than any tag; its points that clear the raised bar are the tag's
// black-white edges, which then stand apart (splitClusters). Every family
// on, no size given.
TEST(Pipeline, TagOnAStripedWallIsFound)
{
	WallScene s;
	s.size = 0.3;
	s.spacing = 0.01;
	s.wall = 4.0;
	s.stripes = 0.15;
	s.stripePeriod = 0.04;
	s.T_G_wall = wallPose(0.3, M_PI / 2, Eigen::Vector3d(3, 1, 1));
	expectOnlyTheWallsTag(s, PipelineParams{}, "clustering");
}

TEST(Pipeline, PlainWallHasNoTags)
{
	WallScene s;
	s.family = "tag36h11";
	s.size = 0.0001;  // a tag too small to be sampled: the wall is plain
	TagDetection truth;
	EXPECT_TRUE(Pipeline().detect(makeWall(s, truth)).tags.empty());
}

TEST(IntermediatePlane, PixelsNeedNotBeFinerThanTheSmallestCell)
{
	// A 6 mm scan renders at 0.6 x its spacing; when the smallest cell a tag
	// in the box could have is 5 cm, pixels of 5 mm (10 per cell) resolve it.
	WallScene s;
	TagDetection truth;
	const auto map = makeWall(s, truth);
	std::vector<uint32_t> all(map.size());
	for (uint32_t i = 0; i < all.size(); i++) all[i] = i;
	OrientedBox box;
	box.center = truth.position();
	box.axes = truth.pose.linear();
	box.extent = Eigen::Vector3d(0.3, 0.3, 0.01);
	const float *xs = map.getPointsBufferRef_x().data(), *ys = map.getPointsBufferRef_y().data(),
				*zs = map.getPointsBufferRef_z().data(), *is = map.getPointsBufferRef_intensity().data();
	IntermediatePlaneParams p;
	p.maxImagePixels = 4000;  // the image edge cap is not what this test is about
	const PlaneImage fine = renderIntermediatePlane(xs, ys, zs, is, all, box, s.spacing, p);
	const PlaneImage capped = renderIntermediatePlane(xs, ys, zs, is, all, box, s.spacing, p, 0.05);
	EXPECT_NEAR(fine.frame.pixel, p.pixelSpacings * s.spacing, 0.2 * p.pixelSpacings * s.spacing);
	EXPECT_DOUBLE_EQ(capped.frame.pixel, 0.05 / p.pixelsPerCell);
	EXPECT_LT(capped.gray.cols, 0.8 * fine.gray.cols);  // 0.8 m of wall: 160 px + padding, not 222
}

TEST(IntermediatePlane, ScannedMaskEndsOneSplatSigmaFromTheScanLines)
{
	// Scan lines 7.2 mm apart, points 2 mm apart along them (a rosette's
	// petals cross a tag like this): the splat sigma is 0.6 x 3.8 mm, so
	// half way between two lines is 1.6 sigma from any point. The image
	// there is the hole filling's guess from the lines beside it, not a
	// measurement; the splats' 5 % reach (2 sigma) covered it.
	const double lines = 0.0072, along = 0.002;
	std::vector<float> xs, ys, zs, is;
	for (double y = -0.2; y <= 0.2001; y += lines)
		for (double x = -0.2; x <= 0.2001; x += along)
		{
			xs.push_back(static_cast<float>(x)), ys.push_back(static_cast<float>(y)), zs.push_back(0);
			is.push_back(x < 0 ? 0.2f : 0.8f);
		}
	std::vector<uint32_t> all(xs.size());
	for (uint32_t i = 0; i < all.size(); i++) all[i] = i;
	OrientedBox box;
	box.center = Eigen::Vector3d::Zero();
	box.axes = Eigen::Matrix3d::Identity();
	box.extent = Eigen::Vector3d(0.18, 0.18, 0.01);
	IntermediatePlaneParams p;
	p.pixelSpacings = 0.2;  // pixels a fifth of sigma: a pixel's centre is where it is tested
	p.maxImagePixels = 4000;
	const PlaneImage plane =
		renderIntermediatePlane(xs.data(), ys.data(), zs.data(), is.data(), all, box, along, p);
	ASSERT_FALSE(plane.gray.empty());
	ASSERT_NEAR(plane.localSpacing, std::sqrt(lines * along), 0.1 * std::sqrt(lines * along));
	const auto scanned = [&](double x, double y) {
		const Eigen::Vector2d px = plane.frame.toImage(Eigen::Vector3d(x, y, 0));
		return plane.measured.at<uint8_t>(static_cast<int>(px.y()), static_cast<int>(px.x())) != 0;
	};
	const double onALine = -0.2 + 27 * lines;
	for (double x : {-0.05, 0.05})
	{
		EXPECT_TRUE(scanned(x + 0.3 * along, onALine + 0.0005));
		EXPECT_FALSE(scanned(x, onALine + 0.5 * lines));
	}
}

TEST(Pipeline, AFarSparseTagIsNotReadAsAnotherId)
{
	// Captured from `tagmap observe` on a simulated 64 x 512 robot scan
	// (share/scenes/localize_site.yaml, run robot, scan 39): tag36h11:0 at
	// 6.9 m, about one point per cell, cropped to 2.5 m around it, sensor
	// frame. The image rendered from it decoded as tag36h11:422 (2 bits
	// wrong by libapriltag's count, pattern fit 0.92); at the fitted pose 6
	// of the 36 code cells hold no point (code_in_points.h), and over the
	// 30 others a random pattern would match that well with P = 2.0e-3, over
	// the budget of 1e-3. The tag may be missed; it must not be
	// reported as another id (without the measured-cells check it was, with
	// either family list).
	const auto map = io::loadPointCloud(std::string(TAGMAP_SOURCE_DIR) + "/tests/data/far-sparse-tag0-misread-as-422.pcd");
	for (const std::string families : {"tag36h11", ""})
	{
		PipelineParams p;
		p.families = parseFamilyList(families);
		const Detections found = Pipeline(p).detect(map);
		for (const TagDetection& t : found.tags)
			EXPECT_TRUE(t.family == "tag36h11" && t.id == 0) << t.family << ":" << t.id << " with families '" << families << "'";
		// Searched alone, tag36h11 gives the read a budget it passes on the
		// image; the measured cells are what reject it.
		if (!families.empty())
		{
			EXPECT_TRUE(std::any_of(found.candidates.begin(), found.candidates.end(), [](const CandidateReport& c) {
				return c.verdict == Verdict::CodeNotInPoints;
			}));
		}
	}
}

mrpt::maps::CPointsMapXYZI wallSeenFromTheOrigin(double tagSize, TagDetection& truth)
{
	WallScene s;
	s.size = tagSize;
	s.spacing = 0.008;
	s.wall = 1.0;
	return tagmap::testing::makeWallInFrontOfTheOrigin(s, truth);
}

std::vector<std::string> stageNames(const Detections& d)
{
	std::vector<std::string> names;
	for (const StageReport& r : d.stages) names.push_back(r.name);
	return names;
}

TEST(Pipeline, ASensorViewReadsTheTagAndAPlainOneStopsThere)
{
	PipelineParams p;
	p.families = {"tag36h11"};
	p.threads = 1;
	p.sensorView.enabled = true;
	const Pipeline pipeline(p);
	TagDetection truth;
	const Detections found = pipeline.detect(wallSeenFromTheOrigin(0.2, truth));
	ASSERT_EQ(found.tags.size(), 1u);
	EXPECT_EQ(found.tags[0].id, truth.id);
	EXPECT_LT((found.tags[0].position() - truth.position()).norm(), 0.005);
	const std::vector<std::string> all = stageNames(found);
	EXPECT_EQ(all.front(), "sensor_view");
	EXPECT_NE(std::find(all.begin(), all.end(), "decode"), all.end());
	EXPECT_EQ(std::find(all.begin(), all.end(), "intensity_gradient"), all.end());

	// Nothing read in the view: the scan's spacing and noise are not even
	// measured.
	const Detections plain = pipeline.detect(wallSeenFromTheOrigin(0.0001, truth));
	EXPECT_TRUE(plain.tags.empty());
	EXPECT_EQ(stageNames(plain), std::vector<std::string>{"sensor_view"});
}

TEST(Pipeline, FindsATagPartlyInAScanGap)
{
	// A band across the tag's border and its last code column holds no
	// point (a rosette's petal gap, an occluder's shadow): the code still
	// shows on the other cells.
	WallScene s;
	s.spacing = 0.008;
	TagDetection truth;
	const auto wall = makeWall(s, truth);
	mrpt::maps::CPointsMapXYZI map;
	const double cell = s.size / 8;
	for (size_t i = 0; i < wall.size(); i++)
	{
		const float x = wall.getPointsBufferRef_x()[i], y = wall.getPointsBufferRef_y()[i],
					z = wall.getPointsBufferRef_z()[i], I = wall.getPointsBufferRef_intensity()[i];
		if (x > 0.5 * s.size - 2.2 * cell && x < 0.5 * s.size - 0.2 * cell && std::abs(y) < 0.5 * s.size + 2 * cell)
			continue;
		map.insertPointRGB(x, y, z, I, 0, 0);
	}
	const Detections found = Pipeline().detect(map);
	ASSERT_EQ(found.tags.size(), 1u);
	EXPECT_EQ(found.tags[0].id, truth.id);
	EXPECT_LT((found.tags[0].position() - truth.position()).norm(), 0.01);
}

TEST(Pipeline, ABoxHoldingADecodedTagStillReadsTheTagBesideIt)
{
	// Two tags 0.36 m apart on one wall: a square window between them
	// holds both. Its read of the first, which a window of its group
	// decoded before it, is not verified again (on_decoded_tag); the
	// second tag, which it also holds, is still read there.
	WallScene a, b;
	a.size = 0.24, b.size = 0.16, b.family = "tag25h9", b.id = 3, b.seed = 2;
	a.wall = b.wall = 0.36;
	a.T_G_wall = wallPose(0, M_PI / 2, Eigen::Vector3d(3, 0, 1));
	b.T_G_wall = wallPose(0, M_PI / 2, Eigen::Vector3d(3.36, 0, 1));
	TagDetection ta, tb;
	mrpt::maps::CPointsMapXYZI map = makeWall(a, ta);
	const mrpt::maps::CPointsMapXYZI second = makeWall(b, tb);
	map.insertAnotherMap(&second, mrpt::poses::CPose3D());
	const Detections found = Pipeline().detect(map, ProgressFn{}, true);
	ASSERT_EQ(found.tags.size(), 2u);
	size_t holdingBoth = 0;
	for (const CandidateReport& c : found.candidates)
	{
		if (c.verdict != Verdict::Decoded) continue;
		bool skipped = false, read = false;
		for (size_t r = 0; r < c.decoded.size(); r++)
		{
			skipped |= c.decoded[r].family == "tag36h11" && c.readVerdicts[r] == Verdict::OnDecodedTag;
			read |= c.decoded[r].family == "tag25h9" && c.readVerdicts[r] == Verdict::Decoded;
		}
		if (!(skipped && read)) continue;
		holdingBoth++;
		ASSERT_TRUE(c.onTagOf.has_value());  // not its verdict, but where its skipped read was decoded
		EXPECT_EQ(found.candidates.at(*c.onTagOf).verdict, Verdict::Decoded);
	}
	EXPECT_GE(holdingBoth, 1u);
}
