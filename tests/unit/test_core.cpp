#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tagmap/atomic_file.h"
#include "tagmap/fast_atan2.h"
#include "tagmap/tag_family.h"
#include "tagmap/tags_json.h"

using namespace tagmap;

TEST(TagFamily, RegistryHasConventionNames)
{
	for (const char* n : {"tag36h11", "tag25h9", "tag16h5", "tagStandard41h12", "tagStandard52h13", "tagCircle21h7",
						  "tagCircle49h12", "tagCustom48h12", "aruco_original", "aruco_4x4_50", "aruco_6x6_250"})
		EXPECT_NE(findFamily(n), nullptr) << n;
	EXPECT_EQ(findFamily("tag36h10"), nullptr);
	EXPECT_EQ(findFamily("tag36h11")->borderCells, 8);
	EXPECT_EQ(findFamily("aruco_4x4_50")->borderCells, 6);
	EXPECT_EQ(findFamily("tagStandard41h12")->borderCells, 5);
}

TEST(TagFamily, UnknownFamilyListsValidOnes)
{
	try
	{
		parseFamilyList("tag36h11,bogus");
		FAIL();
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("bogus"), std::string::npos);
		EXPECT_NE(std::string(e.what()).find("aruco_4x4_50"), std::string::npos);
	}
}

TEST(TagFamily, BitmapHasBlackBorderAndQuietZone)
{
	for (const char* n : {"tag36h11", "aruco_4x4_50"})
	{
		TagBitmap bm = renderTagBitmap(n, 3);
		const int b0 = bm.borderStart, b1 = bm.borderStart + bm.borderCells - 1;
		for (int k = b0; k <= b1; k++)
		{
			EXPECT_EQ(bm.at(b0, k), 0) << n;  // top border row is black
			EXPECT_EQ(bm.at(k, b1), 0) << n;  // right border column is black
		}
		for (int k = 0; k < bm.cells; k++) EXPECT_EQ(bm.at(0, k), 255) << n;  // quiet zone is white
	}
	EXPECT_THROW(renderTagBitmap("tag36h11", 100000), std::invalid_argument);
}

TEST(TagDetection, PoseFromCornersRoundTrip)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(1, -2, 3);
	const auto c = cornersFromPose(T, 0.2);
	const Eigen::Isometry3d back = poseFromCorners(c);
	EXPECT_LT((back.matrix() - T.matrix()).norm(), 1e-9);
}

TEST(TagsJson, WriteReadRoundTrip)
{
	TagDetection d;
	d.family = "tag36h11";
	d.id = 7;
	d.size = 0.164;
	d.pose.translation() = Eigen::Vector3d(1, 2, 3);
	d.corners = cornersFromPose(d.pose, d.size);
	const auto path = (std::filesystem::temp_directory_path() / "tagmap_test_rt.json").string();
	writeTagsJson(path, {d}, "\"scene\": \"x\"");
	const auto back = readTagsJson(path);
	ASSERT_EQ(back.size(), 1u);
	EXPECT_EQ(back[0].family, "tag36h11");
	EXPECT_EQ(back[0].id, 7);
	EXPECT_NEAR(back[0].corners[2].x(), d.corners[2].x(), 1e-6);
	EXPECT_EQ(tagsToJson({}), "{\n  \"tags\": []\n}\n");
}

TEST(AtomicFile, FailedWriteLeavesOldFileUntouched)
{
	const auto path = (std::filesystem::temp_directory_path() / "tagmap_test_atomic.txt").string();
	writeFileAtomically(path, [](std::ostream& o) { o << "good"; });
	EXPECT_THROW(writeFileAtomically(path,
									 [](std::ostream& o) {
										 o << "half";
										 throw std::runtime_error("killed");
									 }),
				 std::runtime_error);
	std::ifstream in(path);
	std::string s;
	in >> s;
	EXPECT_EQ(s, "good");
	for (const auto& e : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
		EXPECT_EQ(e.path().filename().string().find("tagmap_test_atomic.txt.tmp"), std::string::npos);
}

TEST(TagFamily, EveryCodeDrawnInTurnIsItsOwnBitmap)
{
	// forEachTagBitmap redraws one grid: a cell the next code leaves alone
	// would keep the last code's colour.
	for (const char* n : {"tagStandard41h12", "tagCircle21h7", "aruco_5x5_100"})
	{
		int visited = 0, differing = 0;
		forEachTagBitmap(n, [&](int id, const TagBitmap& bm) {
			EXPECT_EQ(id, visited++);
			const TagBitmap own = renderTagBitmap(n, id);
			differing += own.pixels != bm.pixels || own.cells != bm.cells || own.borderStart != bm.borderStart ||
						 own.borderCells != bm.borderCells;
		});
		EXPECT_EQ(visited, findFamily(n)->idCount) << n;
		EXPECT_EQ(differing, 0) << n;
	}
	EXPECT_THROW(forEachTagBitmap("tag99h99", [](int, const TagBitmap&) {}), std::invalid_argument);
}

TEST(TagFamily, CodeCellBitsAreEachCodesWhiteCells)
{
	// Grids of 121 (tag25h9), 144 (tag36h11), 169 (tagCircle49h12: into a
	// third word) and 64 (aruco_4x4_50: one word) cells: the bits are
	// gathered eight cells at a time, and a grid that is no multiple of 8
	// ends with single cells.
	for (const char* n : {"tag25h9", "tag36h11", "tagCircle49h12", "aruco_4x4_50"})
	{
		const std::vector<TagCellBits>& bits = codeCellBits(n);
		ASSERT_EQ(static_cast<int>(bits.size()), findFamily(n)->idCount) << n;
		EXPECT_EQ(&bits, &codeCellBits(n)) << "made once per process";
		int differing = 0;
		for (int id : {0, 1, findFamily(n)->idCount / 2, findFamily(n)->idCount - 1})
		{
			const TagBitmap bm = renderTagBitmap(n, id);
			TagCellBits expected;
			for (size_t k = 0; k < bm.pixels.size(); k++) expected[k] = bm.pixels[k] != 0;
			differing += bits[static_cast<size_t>(id)] != expected;
		}
		EXPECT_EQ(differing, 0) << n;
	}
	EXPECT_THROW(codeCellBits("tag99h99"), std::invalid_argument);
}

TEST(TagFamily, NestedArucoDictionariesNameTheSameMarker)
{
	EXPECT_TRUE(sameMarker("aruco_4x4_50", 7, "aruco_4x4_1000", 7));
	EXPECT_FALSE(sameMarker("aruco_4x4_50", 7, "aruco_5x5_50", 7));
	EXPECT_FALSE(sameMarker("aruco_4x4_50", 7, "aruco_4x4_1000", 8));
	EXPECT_FALSE(sameMarker("aruco_original", 7, "aruco_5x5_1000", 7));
	EXPECT_FALSE(sameMarker("tag36h11", 7, "tag25h9", 7));
}

// The registry's minimum Hamming distance decides which families are read
// only exactly (TagFamilyInfo::weak); check it against the codes themselves,
// every pair and every rotation, on the data cells of the rendered bitmaps.
TEST(TagFamily, MinimumHammingDistanceMatchesTheCodes)
{
	for (const auto& f : supportedFamilies())
	{
		if (f.idCount > 2200) continue;  // tagStandard52h13 and the like: too many pairs for a unit test
		// Whole grid: the quiet zone and the border are the same in every
		// code (distance 0), and some layouts (tagStandard, tagCircle) have
		// data bits outside the border ring.
		const int n = renderTagBitmap(f.name, 0).cells;
		auto code = [&](const TagBitmap& bm, int rotation) {
			std::vector<uint8_t> bits;
			for (int r = 0; r < n; r++)
				for (int c = 0; c < n; c++)
				{
					int rr = r, cc = c;
					for (int k = 0; k < rotation; k++) std::tie(rr, cc) = std::make_pair(cc, n - 1 - rr);
					bits.push_back(bm.at(rr, cc) != 0);
				}
			return bits;
		};
		std::vector<std::array<std::vector<uint8_t>, 4>> codes;
		for (int id = 0; id < f.idCount; id++)
		{
			const TagBitmap bm = renderTagBitmap(f.name, id);
			codes.push_back({code(bm, 0), code(bm, 1), code(bm, 2), code(bm, 3)});
		}
		auto distance = [](const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
			int d = 0;
			for (size_t k = 0; k < a.size(); k++) d += a[k] != b[k];
			return d;
		};
		int fewest = 1 << 30;
		for (size_t i = 0; i < codes.size(); i++)
		{
			for (int r = 1; r < 4; r++) fewest = std::min(fewest, distance(codes[i][0], codes[i][r]));
			for (size_t j = i + 1; j < codes.size(); j++)
				for (int r = 0; r < 4; r++) fewest = std::min(fewest, distance(codes[i][0], codes[j][r]));
		}
		EXPECT_EQ(f.minHamming, fewest) << f.name;
	}
}

TEST(FastAtan2, WithinItsBoundOfStdAtan2EverywhereOnTheCircleAndAtTheAxes)
{
	// Every direction (10^5 around the circle, at radii from 1e-3 to 1e3),
	// the axes and the origin: within the bound the sensor view relies on.
	double worst = 0;
	for (int k = 0; k < 100000; k++)
		for (double r : {1e-3, 1.0, 1e3})
		{
			const double a = -M_PI + 2 * M_PI * k / 100000, y = r * std::sin(a), x = r * std::cos(a);
			worst = std::max(worst, std::abs(tagmap::fastAtan2(y, x) - std::atan2(y, x)));
		}
	EXPECT_LT(worst, 6e-9);
	EXPECT_DOUBLE_EQ(tagmap::fastAtan2(0, 1), 0);
	EXPECT_NEAR(tagmap::fastAtan2(1, 0), M_PI / 2, 1e-15);
	EXPECT_NEAR(tagmap::fastAtan2(0, -1), M_PI, 1e-15);
	EXPECT_NEAR(tagmap::fastAtan2(-1, 0), -M_PI / 2, 1e-15);
	EXPECT_NEAR(tagmap::fastAtan2(1, 1), M_PI / 4, 6e-9);
	EXPECT_EQ(tagmap::fastAtan2(0, 0), 0);
}
