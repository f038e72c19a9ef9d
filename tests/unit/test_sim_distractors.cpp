// Clutter distractors: each kind draws what it claims (window grids, zebra
// crossings, QR-like codes), and the bordered square, the hardest negative,
// is read by no decoder while the same square with a real code is.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "tagmap/errors.h"
#include "tagmap/sim/distractor.h"
#include "tagmap/sim/non_tag_interior.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_family.h"

using namespace tagmap;
using namespace tagmap::sim;

namespace
{
Texture textureOf(DistractorKind kind, double w, double h, double cell, uint64_t seed = 3)
{
	DistractorSpec s;
	s.kind = kind;
	s.width = w;
	s.height = h;
	s.cell = cell;
	s.seed = seed;
	const SceneObject o = makeDistractor(s);
	EXPECT_EQ(o.faces.size(), 1u);
	return o.faces[0].texture;
}

float cellAt(const Texture& t, int r, int c) { return t.cells[static_cast<size_t>(r) * t.cols + c]; }

// The texture as an 8-bit image, `px` pixels per cell, two cells of white around.
cv::Mat image(const Texture& t, int px = 12)
{
	cv::Mat img((t.rows + 4) * px, (t.cols + 4) * px, CV_8U, cv::Scalar(255));
	for (int r = 0; r < t.rows; r++)
		for (int c = 0; c < t.cols; c++)
			img(cv::Rect((c + 2) * px, (r + 2) * px, px, px)).setTo(cv::Scalar(cellAt(t, r, c) > 0.5f ? 255 : 0));
	return img;
}

std::vector<std::string> allFamilies()
{
	std::vector<std::string> names;
	for (const auto& f : supportedFamilies()) names.push_back(f.name);
	return names;
}
}  // namespace

TEST(SimDistractors, WindowGridIsWholeWindowsInAFrame)
{
	// 2 x 1 m, 0.5 m pitch: 20 x 10 texture cells of 0.1 m; 3 x 1 whole
	// windows of 4 x 4 dark cells, mullions and frame light.
	const Texture t = textureOf(DistractorKind::WindowGrid, 2.0, 1.0, 0.5);
	ASSERT_EQ(t.cols, 20);
	ASSERT_EQ(t.rows, 10);
	EXPECT_DOUBLE_EQ(t.cellW, 0.1);
	size_t dark = 0;
	for (float v : t.cells) dark += v < 0.5f;
	EXPECT_EQ(dark, 3u * 16u);
	for (int r = 0; r < t.rows; r++) EXPECT_GT(cellAt(t, r, 0), 0.5f);  // frame
	EXPECT_LT(cellAt(t, 1, 1), 0.5f);  // first pane
	EXPECT_GT(cellAt(t, 1, 5), 0.5f);  // mullion
}

TEST(SimDistractors, ZebraIsWornLightBarsOnAsphalt)
{
	const Texture t = textureOf(DistractorKind::Zebra, 4.0, 3.0, 0.5);
	ASSERT_EQ(t.cols, 8);
	ASSERT_EQ(t.rows, 6);
	EXPECT_LT(t.base, 0.5f);  // asphalt around the sheet's grid too
	float lo = 1, hi = 0;
	for (int r = 0; r < t.rows; r++)
		for (int c = 0; c < t.cols; c++)
		{
			const bool bar = c % 2 == 1 && r > 0 && r + 1 < t.rows;
			if (!bar)
			{
				EXPECT_LT(cellAt(t, r, c), 0.5f) << r << "," << c;
				continue;
			}
			lo = std::min(lo, cellAt(t, r, c));
			hi = std::max(hi, cellAt(t, r, c));
		}
	EXPECT_GE(lo, 0.7f * 0.85f - 1e-6f);
	EXPECT_LE(hi, 0.85f);
	EXPECT_LT(lo, hi);  // worn unevenly
}

TEST(SimDistractors, QrLikeHasThreeFindersNotFour)
{
	const Texture t = textureOf(DistractorKind::QrLike, 1.0, 1.0, 1.0 / 25);  // 21 modules + quiet zone
	ASSERT_EQ(t.cols, 25);
	auto isFinder = [&](int top, int left) {
		for (int r = 0; r < 7; r++)
			for (int c = 0; c < 7; c++)
			{
				const int ring = std::min(std::min(r, c), std::min(6 - r, 6 - c));
				if ((cellAt(t, top + r, left + c) < 0.5f) != (ring != 1)) return false;
			}
		return true;
	};
	EXPECT_TRUE(isFinder(2, 2));
	EXPECT_TRUE(isFinder(2, 16));
	EXPECT_TRUE(isFinder(16, 2));
	EXPECT_FALSE(isFinder(16, 16));
	for (int c = 0; c < t.cols; c++) EXPECT_GT(cellAt(t, 0, c), 0.5f);  // quiet zone
}

TEST(SimDistractors, BorderedSquareIsNoTagButTheSameSquareWithACodeIs)
{
	// 10 cells: quiet zone, border, 6 x 6 interior, like tag36h11 and aruco 6x6.
	const int n = 6;
	const TagDecoder decoder(allFamilies());
	for (uint64_t seed = 1; seed <= 5; seed++)
	{
		const Texture t = textureOf(DistractorKind::BorderedSquare, 0.5, 0.5, 0.05, seed);
		ASSERT_EQ(t.cols, 10);
		std::vector<bool> interior;
		for (int r = 0; r < t.rows; r++)
			for (int c = 0; c < t.cols; c++)
			{
				const bool ring = std::max(std::abs(2 * r - 9), std::abs(2 * c - 9)) == 7;
				if (ring)
				{
					EXPECT_LT(cellAt(t, r, c), 0.5f);
				}
				if (r >= 2 && r < 8 && c >= 2 && c < 8) interior.push_back(cellAt(t, r, c) < 0.5f);
			}
		EXPECT_GE(distanceToNearestCode(interior, n, true), 0);
		EXPECT_TRUE(decoder.decode(image(t)).empty()) << "seed " << seed;

		// Control: the same square carrying tag36h11 #5's interior is read.
		Texture tag = t;
		const TagBitmap bm = renderTagBitmap("tag36h11", 5);
		std::vector<bool> code;
		for (int r = 0; r < n; r++)
			for (int c = 0; c < n; c++)
			{
				const bool black = bm.at(bm.borderStart + 1 + r, bm.borderStart + 1 + c) == 0;
				tag.cells[static_cast<size_t>(r + 2) * tag.cols + c + 2] = black ? 0.06f : 0.85f;
				code.push_back(black);
			}
		EXPECT_EQ(distanceToNearestCode(code, n), 0);
		const auto reads = decoder.decode(image(tag));
		ASSERT_FALSE(reads.empty());
		EXPECT_EQ(reads[0].family, "tag36h11");
		EXPECT_EQ(reads[0].id, 5);
	}
}

TEST(SimDistractors, SheetsTooSmallForTheirKindAreSceneErrors)
{
	auto scene = [](const std::string& distractor) {
		return "name: x\nobjects: []\ndistractors:\n  - {name: d, position: [0, 0, 0], " + distractor +
			   "}\nsensors:\n  - {name: s, type: spinning}\n"
			   "runs:\n  - {name: r, sensor: s, duration: 0.1, waypoints: [{position: [0, 0, 0]}]}\n";
	};
	EXPECT_NO_THROW(parseScene(scene("type: qr_like, size: [0.95, 1], cell: 0.05"), "x.yaml"));
	EXPECT_THROW(parseScene(scene("type: qr_like, size: [0.9, 1], cell: 0.05"), "x.yaml"), InputError);
	EXPECT_NO_THROW(parseScene(scene("type: bordered_square, size: [0.36, 0.36], cell: 0.05"), "x.yaml"));
	EXPECT_THROW(parseScene(scene("type: bordered_square, size: [0.34, 0.5], cell: 0.05"), "x.yaml"), InputError);
	EXPECT_THROW(parseScene(scene("type: hopscotch, size: [1, 1]"), "x.yaml"), InputError);
}
