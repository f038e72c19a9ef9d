#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <opencv2/core.hpp>
#include <opencv2/core/base.hpp>
#include <opencv2/imgproc.hpp>

#include "tagmap/image_variants.h"
#include "tagmap/read_evidence.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_family.h"
#include "tagmap/tag_quads.h"

using namespace tagmap;

namespace
{
// Draws a tag bitmap with `px` pixels per cell at offset `pad`; returns the
// image and the border square's corners (vertex order) in pixel-edge coordinates.
cv::Mat drawTag(const std::string& family, int id, int px, int pad, std::array<Eigen::Vector2d, 4>& corners)
{
	const TagBitmap bm = renderTagBitmap(family, id);
	const int n = bm.cells * px + 2 * pad;
	cv::Mat img(n, n, CV_8UC1, cv::Scalar(255));
	for (int r = 0; r < bm.cells; r++)
		for (int c = 0; c < bm.cells; c++) img(cv::Rect(pad + c * px, pad + r * px, px, px)).setTo(bm.at(r, c));
	const double b0 = pad + bm.borderStart * px, b1 = b0 + bm.borderCells * px;
	corners = {Eigen::Vector2d(b0, b0), Eigen::Vector2d(b1, b0), Eigen::Vector2d(b1, b1), Eigen::Vector2d(b0, b1)};
	return img;
}
}  // namespace

class DecoderFamilies : public ::testing::TestWithParam<const char*>
{
};

TEST_P(DecoderFamilies, DecodesUprightAndMirroredWithVertexOrder)
{
	const std::string family = GetParam();
	std::array<Eigen::Vector2d, 4> truth;
	cv::Mat img = drawTag(family, 5, 12, 30, truth);
	TagDecoder decoder({family});
	for (bool mirror : {false, true})
	{
		cv::Mat in = img.clone();
		std::array<Eigen::Vector2d, 4> expected = truth;
		if (mirror)
		{
			cv::flip(img, in, 1);
			for (auto& c : expected) c.x() = img.cols - c.x();
		}
		auto found = decoder.decode(in);
		// aruco_original is not mirror-safe: the mirror image of a marker is
		// another valid marker, so both readings come back (the pipeline
		// picks one by geometry). Every other family reads one way only.
		const size_t expectedCount = family == "aruco_original" ? 2 : 1;
		ASSERT_EQ(found.size(), expectedCount) << family << " mirror=" << mirror;
		auto it = std::find_if(found.begin(), found.end(), [&](const DecodedTag2D& d) { return d.mirrored == mirror; });
		ASSERT_NE(it, found.end());
		EXPECT_EQ(it->family, family);
		EXPECT_EQ(it->id, 5);
		for (int k = 0; k < 4; k++) EXPECT_LT((it->corners[k] - expected[k]).norm(), 1.0) << family << " vertex " << k;
	}
}

INSTANTIATE_TEST_SUITE_P(All, DecoderFamilies,
						 ::testing::Values("tag36h11", "tag25h9", "tagStandard41h12", "tagCircle21h7", "aruco_4x4_50",
										   "aruco_6x6_250", "aruco_original"));

TEST(TagDecoder, NestedArucoDictionaryReportsSmallestHoldingTheId)
{
	std::array<Eigen::Vector2d, 4> truth;
	cv::Mat img = drawTag("aruco_4x4_1000", 120, 12, 30, truth);
	TagDecoder decoder({"aruco_4x4_50", "aruco_4x4_250", "aruco_4x4_1000"});
	const auto found = decoder.decode(img);
	ASSERT_EQ(found.size(), 1u);
	EXPECT_EQ(found[0].family, "aruco_4x4_250");
	EXPECT_EQ(found[0].id, 120);
}

TEST(ImageVariants, SmoothedHalfSizeReadsATagUnderGrainAndStripes)
{
	// A dense map's candidate image: each pixel's intensity noise (as large
	// as the print's contrast and more) and the stripes of alternating scan
	// lines, on a tag of 10 pixels a cell. Smoothed at half size, every one
	// of eight such images reads; the plain half-size image loses some, the
	// full-size ones most.
	TagDecoder d(searchFamilies(parseFamilyList("")));
	const TagBitmap bm = renderTagBitmap("tag36h11", 7);
	std::map<std::string, int> read;
	for (double noise : {80.0, 100.0})
		for (unsigned seed = 0; seed < 4; seed++)
		{
			std::mt19937 rng(seed);
			std::normal_distribution<double> grain(0, noise);
			const int px = 10, margin = 30, side = bm.cells * px + 2 * margin;
			cv::Mat img(side, side, CV_8UC1);
			for (int r = 0; r < side; r++)
				for (int c = 0; c < side; c++)
				{
					const int gr = (r - margin) / px, gc = (c - margin) / px;
					const bool inGrid = r >= margin && c >= margin && gr < bm.cells && gc < bm.cells;
					const double stripe = (r / 2) % 2 ? 25 : -25;
					img.at<uint8_t>(r, c) =
						cv::saturate_cast<uint8_t>((inGrid && !bm.at(gr, gc) ? 60 : 200) + stripe + grain(rng));
				}
			for (const ImageVariant& v : makeImageVariants(img, {"raw", "otsu", "half", "half_smooth"}))
				for (const DecodedTag2D& t : d.decode(v.gray)) read[v.name] += t.family == "tag36h11" && t.id == 7;
		}
	EXPECT_EQ(read["half_smooth"], 8);
	EXPECT_LT(read["half"], read["half_smooth"]);
	EXPECT_LT(read["raw"], read["half"]);
}

TEST(TagDecoder, BlankImageDecodesNothing)
{
	cv::Mat img(200, 200, CV_8UC1, cv::Scalar(200));
	TagDecoder decoder({"tag36h11", "tag16h5", "aruco_4x4_50"});
	EXPECT_TRUE(decoder.decode(img).empty());
}

namespace
{
// The right `fraction` of the border square of an image from drawTag()
// left unscanned: its pixels hold the opposite of the tag (the worst a hole
// filling can guess) and the returned mask marks them as not measured.
cv::Mat eraseRightPart(cv::Mat& img, const std::array<Eigen::Vector2d, 4>& corners, double fraction)
{
	cv::Mat measured(img.size(), CV_8UC1, cv::Scalar(255));
	const int x0 = static_cast<int>(corners[1].x() - fraction * (corners[1].x() - corners[0].x()));
	const cv::Rect band(x0, 0, img.cols - x0, img.rows);
	cv::Mat part = img(band);
	cv::bitwise_not(part, part);
	measured(band).setTo(0);
	return measured;
}
}  // namespace

TEST(SoftTagDecoder, ReadsATagPartlyInAScanGapOnItsScannedCells)
{
	std::array<Eigen::Vector2d, 4> corners;
	cv::Mat img = drawTag("tag36h11", 5, 12, 30, corners);
	const cv::Mat measured = eraseRightPart(img, corners, 0.3);
	const SoftTagDecoder decoder({"tag36h11"});
	const std::vector<Quad> quads = {corners};
	// On the painted-over cells as they look, the code is not there.
	for (const DecodedTag2D& d : decoder.decode(img, quads)) EXPECT_NE(d.id, 5);
	const std::vector<DecodedTag2D> found = decoder.decode(img, quads, &measured);
	ASSERT_EQ(found.size(), 1u);
	EXPECT_EQ(found[0].id, 5);
	EXPECT_FALSE(found[0].mirrored);
	for (int k = 0; k < 4; k++) EXPECT_LT((found[0].corners[k] - corners[k]).norm(), 1e-9);
	// The read stands on its scanned cells: chance, border and quiet zone.
	const ReadEvidence e = assessMeasuredRead(img, measured, found[0], 8, {"tag36h11"}, {});
	EXPECT_FALSE(e.rejection) << verdictName(*e.rejection);
	EXPECT_GT(e.erasures, 0);
	EXPECT_TRUE(assessRead(img, found[0], 8, {"tag36h11"}, {}).rejection);
}

TEST(SoftTagDecoder, MarginIsThePearsonCorrelationOnTheScannedCells)
{
	// A noisy tag partly in a gap: the read's margin is 100 x the Pearson
	// correlation of its code with the scanned cells that differ between
	// codes, computed here the plain way.
	std::array<Eigen::Vector2d, 4> corners;
	cv::Mat img = drawTag("tag36h11", 5, 12, 30, corners);
	for (int r = 0; r < img.rows; r++)
		for (int c = 0; c < img.cols; c++)
		{
			const int cell = (r / 12) * 5 + (c / 12) * 3;  // a grey offset per cell, as sparse cells have
			img.at<uint8_t>(r, c) = cv::saturate_cast<uint8_t>(60 + img.at<uint8_t>(r, c) / 2 + (cell % 9 - 4) * 15);
		}
	const cv::Mat measured = eraseRightPart(img, corners, 0.3);
	const std::vector<DecodedTag2D> found = SoftTagDecoder({"tag36h11"}).decode(img, {corners}, &measured);
	ASSERT_EQ(found.size(), 1u);
	ASSERT_EQ(found[0].id, 5);

	const TagBitmap own = renderTagBitmap("tag36h11", 5);
	std::vector<int> whiteCount(own.pixels.size(), 0);
	const int codes = findFamily("tag36h11")->idCount;
	for (int id = 0; id < codes; id++)
	{
		const TagBitmap bm = renderTagBitmap("tag36h11", id);
		for (size_t k = 0; k < bm.pixels.size(); k++) whiteCount[k] += bm.pixels[k] != 0;
	}
	const std::vector<float> cells = sampleMeasuredCells(img, measured, found[0].corners, own.cells, own.borderStart,
														 own.borderStart + own.borderCells);
	std::vector<double> x, y;
	for (size_t k = 0; k < cells.size(); k++)
		if (whiteCount[k] != 0 && whiteCount[k] != codes && !std::isnan(cells[k]))
			x.push_back(cells[k]), y.push_back(own.pixels[k] != 0);
	ASSERT_GT(x.size(), 18u);
	ASSERT_LT(x.size(), 36u);  // some are erased
	const auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); };
	const double mx = mean(x), my = mean(y);
	double sxy = 0, sxx = 0, syy = 0;
	for (size_t k = 0; k < x.size(); k++)
		sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx), syy += (y[k] - my) * (y[k] - my);
	const double r = sxy / std::sqrt(sxx * syy);
	EXPECT_LT(r, 0.99);  // the noise shows
	EXPECT_NEAR(found[0].margin, 100 * r, 1e-6);
}

TEST(SoftTagDecoder, MostlyUnscannedTagIsNotRead)
{
	std::array<Eigen::Vector2d, 4> corners;
	cv::Mat img = drawTag("tag36h11", 5, 12, 30, corners);
	const cv::Mat measured = eraseRightPart(img, corners, 0.6);
	const SoftTagDecoder decoder({"tag36h11"});
	EXPECT_TRUE(decoder.decode(img, {corners}, &measured).empty());
	// Nor does a read of it pass with its frame mostly unscanned.
	DecodedTag2D read;
	read.family = "tag36h11";
	read.id = 5;
	read.corners = corners;
	EXPECT_TRUE(assessMeasuredRead(img, measured, read, 8, {"tag36h11"}, {}).rejection);
}

// Families whose border ring is white (libapriltag's reversed border) are
// outlined by the black ring around it or by the whole printed tag; the
// soft decoder reads them from any of those quads, noisy and blurred, and
// reports the border square's corners. Before, it read none of them.
TEST(SoftTagDecoder, ReadsWhiteBorderFamiliesFromTheirDarkOutlines)
{
	for (const char* family : {"tagStandard41h12", "tagStandard52h13", "tagCircle49h12"})
	{
		std::array<Eigen::Vector2d, 4> border;
		const int px = 12, pad = 30;
		cv::Mat img = drawTag(family, 7, px, pad, border);
		cv::GaussianBlur(img, img, cv::Size(), 0.3 * px);
		std::mt19937 rng(7);
		std::normal_distribution<double> noise(0, 40);
		for (int r = 0; r < img.rows; r++)
			for (int c = 0; c < img.cols; c++)
				img.at<uint8_t>(r, c) = cv::saturate_cast<uint8_t>(img.at<uint8_t>(r, c) * 0.8 + 25 + noise(rng));
		const TagBitmap bm = renderTagBitmap(family, 7);
		const SoftTagDecoder decoder({family});
		// The quad outlining the border square grown by `out` cells on every side.
		const auto outline = [&](double out) {
			const double b0 = pad + (bm.borderStart - out) * px, b1 = pad + (bm.borderStart + bm.borderCells + out) * px;
			return Quad{Eigen::Vector2d(b0, b0), Eigen::Vector2d(b1, b0), Eigen::Vector2d(b1, b1), Eigen::Vector2d(b0, b1)};
		};
		// The quad as each square: the border (white), the black ring one
		// cell out, the whole printed tag (inside the one-cell quiet zone).
		for (int out : {0, 1, bm.borderStart - 1})
		{
			const std::vector<DecodedTag2D> found = decoder.decode(img, {outline(out)});
			ASSERT_EQ(found.size(), 1u) << family << " outline " << out << " cells out";
			EXPECT_EQ(found[0].id, 7) << family;
			EXPECT_FALSE(found[0].mirrored);
			for (int k = 0; k < 4; k++) EXPECT_LT((found[0].corners[k] - border[k]).norm(), 1e-6) << family;
		}
		// Half a ring off, the frame does not fit: no read.
		EXPECT_TRUE(decoder.decode(img, {outline(0.5)}).empty()) << family;
		// A scan's sensor view leaves these families to libapriltag.
		EXPECT_TRUE(decoder.decode(img, {border}, nullptr, false).empty()) << family;
	}
}

TEST(ReadEvidence, MeasuredReadNeedsItsFrameScanned)
{
	// Every code cell scanned and right, the border ring and the quiet zone
	// not scanned at all: nothing shows that the code is framed like a tag
	// (and not part of a larger pattern).
	std::array<Eigen::Vector2d, 4> corners;
	const cv::Mat img = drawTag("tag36h11", 5, 12, 30, corners);
	const double cell = (corners[1].x() - corners[0].x()) / 8;
	cv::Mat measured(img.size(), CV_8UC1, cv::Scalar(0));
	const int inner = static_cast<int>(corners[0].x() + cell), side = static_cast<int>(6 * cell);
	measured(cv::Rect(inner, inner, side, side)).setTo(255);
	DecodedTag2D read;
	read.family = "tag36h11";
	read.id = 5;
	read.corners = corners;
	const ReadEvidence e = assessMeasuredRead(img, measured, read, 8, {"tag36h11"}, {});
	EXPECT_EQ(e.bitErrors, 0);
	ASSERT_TRUE(e.rejection);
	EXPECT_EQ(*e.rejection, Verdict::NoBorder);
	// The same read with its frame scanned passes.
	measured.setTo(255);
	EXPECT_FALSE(assessMeasuredRead(img, measured, read, 8, {"tag36h11"}, {}).rejection);
}

// A tag at the edge of a scan loses part of its ring (random_020 of the
// randomized scenes: a Livox rosette thins out at its rim, and the bottom
// row of a tag36h11's ring read grey while all 36 code cells read right).
// The ring's white cells count against the code's evidence: an exact code
// outweighs one side of the ring washed out, not a ring mostly gone.
TEST(ReadEvidence, AnExactCodeOutweighsOneWashedOutSideOfItsRing)
{
	std::array<Eigen::Vector2d, 4> corners;
	const cv::Mat img = drawTag("tag36h11", 5, 12, 30, corners);
	const int px = 12, b0 = static_cast<int>(corners[0].x()), b1 = static_cast<int>(corners[2].x());
	DecodedTag2D read;
	read.family = "tag36h11";
	read.id = 5;
	read.corners = corners;
	cv::Mat oneSide = img.clone();
	oneSide(cv::Rect(b0, b1 - px, b1 - b0, px)).setTo(255);  // the ring's bottom row: 8 of its 28 cells
	const ReadEvidence e = assessRead(oneSide, read, 8, {"tag36h11"}, {});
	EXPECT_EQ(e.bitErrors, 0);
	EXPECT_EQ(e.borderErrors, 8);
	EXPECT_FALSE(e.rejection) << verdictName(*e.rejection);
	// Three sides of the ring gone: the ring says this is no tag's frame.
	cv::Mat threeSides = oneSide.clone();
	threeSides(cv::Rect(b0, b0, b1 - b0, px)).setTo(255);
	threeSides(cv::Rect(b0, b0, px, b1 - b0)).setTo(255);
	const ReadEvidence gone = assessRead(threeSides, read, 8, {"tag36h11"}, {});
	EXPECT_EQ(gone.bitErrors, 0);
	ASSERT_TRUE(gone.rejection);
	EXPECT_EQ(*gone.rejection, Verdict::NoBorder);
}
