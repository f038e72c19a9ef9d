#include "tagmap/tag_family.h"

#include <apriltag/apriltag.h>
#include <apriltag/tag16h5.h>
#include <apriltag/tag25h9.h>
#include <apriltag/tag36h11.h>
#include <apriltag/tagCircle21h7.h>
#include <apriltag/tagCircle49h12.h>
#include <apriltag/tagCustom48h12.h>
#include <apriltag/tagStandard41h12.h>
#include <apriltag/tagStandard52h13.h>

#include <opencv2/aruco.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "tagmap/apriltag_families.h"

namespace tagmap
{
namespace
{
struct ArucoDictName
{
	const char* name;
	int dict;
	int idCount;
	int dataBits;  // marker side in data bits (the border adds one on each side)
	int minHamming;  // measured over all code pairs and rotations (test_core checks it)
};

const ArucoDictName kArucoDicts[] = {
	{"aruco_original", cv::aruco::DICT_ARUCO_ORIGINAL, 1024, 5, 0},  // some codes are their own rotation
	{"aruco_4x4_50", cv::aruco::DICT_4X4_50, 50, 4, 4},
	{"aruco_4x4_100", cv::aruco::DICT_4X4_100, 100, 4, 3},
	{"aruco_4x4_250", cv::aruco::DICT_4X4_250, 250, 4, 3},
	{"aruco_4x4_1000", cv::aruco::DICT_4X4_1000, 1000, 4, 2},
	{"aruco_5x5_50", cv::aruco::DICT_5X5_50, 50, 5, 8},
	{"aruco_5x5_100", cv::aruco::DICT_5X5_100, 100, 5, 7},
	{"aruco_5x5_250", cv::aruco::DICT_5X5_250, 250, 5, 6},
	{"aruco_5x5_1000", cv::aruco::DICT_5X5_1000, 1000, 5, 5},
	{"aruco_6x6_50", cv::aruco::DICT_6X6_50, 50, 6, 13},
	{"aruco_6x6_100", cv::aruco::DICT_6X6_100, 100, 6, 12},
	{"aruco_6x6_250", cv::aruco::DICT_6X6_250, 250, 6, 11},
	{"aruco_6x6_1000", cv::aruco::DICT_6X6_1000, 1000, 6, 9},
	{"aruco_7x7_50", cv::aruco::DICT_7X7_50, 50, 7, 19},
	{"aruco_7x7_100", cv::aruco::DICT_7X7_100, 100, 7, 18},
	{"aruco_7x7_250", cv::aruco::DICT_7X7_250, 250, 7, 17},
	{"aruco_7x7_1000", cv::aruco::DICT_7X7_1000, 1000, 7, 14},
};

std::vector<TagFamilyInfo> buildRegistry()
{
	std::vector<TagFamilyInfo> out;
	for (const auto& name : aprilTagFamilyNames())
	{
		AprilTagFamilyPtr fam = createAprilTagFamily(name);
		out.push_back({name, TagSystem::AprilTag, static_cast<int>(fam->ncodes), fam->width_at_border,
					   static_cast<int>(fam->h)});
	}
	for (const auto& d : kArucoDicts)
		out.push_back({d.name, TagSystem::ArUco, d.idCount, d.dataBits + 2, d.minHamming});
	return out;
}

const ArucoDictName& arucoDict(const std::string& name)
{
	for (const auto& d : kArucoDicts)
		if (name == d.name) return d;
	throw std::invalid_argument("unknown ArUco dictionary '" + name + "'");
}

}  // namespace

// ---- AprilTag family objects (shared with the decoder stage) -------------

const std::vector<std::string>& aprilTagFamilyNames()
{
	static const std::vector<std::string> names = {
		"tag36h11",		 "tag25h9",		  "tag16h5",	   "tagStandard41h12",
		"tagStandard52h13", "tagCircle21h7", "tagCircle49h12", "tagCustom48h12"};
	return names;
}

AprilTagFamilyPtr createAprilTagFamily(const std::string& name)
{
	using Ctor = apriltag_family_t* (*)();
	using Dtor = void (*)(apriltag_family_t*);
	struct Entry
	{
		const char* name;
		Ctor create;
		Dtor destroy;
	};
	static const Entry entries[] = {
		{"tag36h11", tag36h11_create, tag36h11_destroy},
		{"tag25h9", tag25h9_create, tag25h9_destroy},
		{"tag16h5", tag16h5_create, tag16h5_destroy},
		{"tagStandard41h12", tagStandard41h12_create, tagStandard41h12_destroy},
		{"tagStandard52h13", tagStandard52h13_create, tagStandard52h13_destroy},
		{"tagCircle21h7", tagCircle21h7_create, tagCircle21h7_destroy},
		{"tagCircle49h12", tagCircle49h12_create, tagCircle49h12_destroy},
		{"tagCustom48h12", tagCustom48h12_create, tagCustom48h12_destroy},
	};
	for (const auto& e : entries)
		if (name == e.name) return AprilTagFamilyPtr(e.create(), e.destroy);
	throw std::invalid_argument("unknown AprilTag family '" + name + "'");
}

cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const std::string& name)
{
	return cv::aruco::getPredefinedDictionary(arucoDict(name).dict);
}

// ---- registry -----------------------------------------------------------

const std::vector<TagFamilyInfo>& supportedFamilies()
{
	static const std::vector<TagFamilyInfo> registry = buildRegistry();
	return registry;
}

const TagFamilyInfo* findFamily(const std::string& name)
{
	for (const auto& f : supportedFamilies())
		if (f.name == name) return &f;
	return nullptr;
}

namespace
{
bool nestedAruco(const TagFamilyInfo* f) { return f && f->system == TagSystem::ArUco && f->name != "aruco_original"; }
}  // namespace

bool sameMarker(const std::string& familyA, int idA, const std::string& familyB, int idB)
{
	if (idA != idB) return false;
	if (familyA == familyB) return true;
	const TagFamilyInfo *a = findFamily(familyA), *b = findFamily(familyB);
	return nestedAruco(a) && nestedAruco(b) && a->borderCells == b->borderCells && idA < std::min(a->idCount, b->idCount);
}

std::vector<std::string> searchFamilies(const std::vector<std::string>& requested)
{
	std::vector<std::string> out;
	for (const auto& name : requested)
	{
		const TagFamilyInfo* f = findFamily(name);
		if (!f) continue;
		bool dominated = false;
		for (const auto& other : requested)
		{
			const TagFamilyInfo* g = findFamily(other);
			if (nestedAruco(f) && nestedAruco(g) && g->borderCells == f->borderCells && g->idCount > f->idCount)
				dominated = true;
		}
		if (!dominated && std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
	}
	return out;
}

std::string reportedFamily(const std::vector<std::string>& requested, const std::string& searched, int id)
{
	const TagFamilyInfo* s = findFamily(searched);
	if (!nestedAruco(s)) return searched;
	const TagFamilyInfo* best = nullptr;
	for (const auto& name : requested)
	{
		const TagFamilyInfo* f = findFamily(name);
		if (nestedAruco(f) && f->borderCells == s->borderCells && id < f->idCount && (!best || f->idCount < best->idCount))
			best = f;
	}
	return best ? best->name : "";
}

std::string markerFamily(const std::string& family, int id)
{
	std::vector<std::string> all;
	for (const auto& f : supportedFamilies()) all.push_back(f.name);
	return reportedFamily(all, family, id);
}

std::string supportedFamilyList()
{
	std::string s;
	for (const auto& f : supportedFamilies()) s += (s.empty() ? "" : ", ") + f.name;
	return s;
}

std::vector<std::string> parseFamilyList(const std::string& commaSeparated)
{
	std::vector<std::string> out;
	std::stringstream ss(commaSeparated);
	std::string item;
	while (std::getline(ss, item, ','))
	{
		if (item.empty()) continue;
		if (!findFamily(item))
			throw std::invalid_argument(
				"unknown tag family '" + item + "'; valid families: " + supportedFamilyList());
		out.push_back(item);
	}
	if (out.empty())
		for (const auto& f : supportedFamilies()) out.push_back(f.name);
	return out;
}

// ---- bitmaps --------------------------------------------------------------

namespace
{
// The family object renderTagBitmap() draws with, made once per process:
// making one per call (the largest holds 65 k codes) was most of the time
// of drawing every code of a family (the soft decoder's tables). Only read.
const apriltag_family_t* drawingFamily(const std::string& name)
{
	static std::mutex mutex;
	static std::map<std::string, AprilTagFamilyPtr> made;
	std::lock_guard<std::mutex> lock(mutex);
	auto it = made.find(name);
	if (it == made.end()) it = made.emplace(name, createAprilTagFamily(name)).first;
	return it->second.get();
}

const TagFamilyInfo& checkedFamily(const std::string& family)
{
	const TagFamilyInfo* info = findFamily(family);
	if (!info)
		throw std::invalid_argument(
			"unknown tag family '" + family + "'; valid families: " + supportedFamilyList());
	return *info;
}

// An AprilTag code as libapriltag draws it, 1 pixel per cell, into `bm`'s
// cells inside its quiet zone (every one of them written).
void drawAprilTag(const apriltag_family_t* fam, int id, TagBitmap& bm)
{
	image_u8_t* im = apriltag_to_image(const_cast<apriltag_family_t*>(fam), id);
	for (int r = 0; r < im->height; r++)
		for (int c = 0; c < im->width; c++)
			bm.pixels[(r + 1) * bm.cells + (c + 1)] = im->buf[r * im->stride + c] ? 255 : 0;
	// libapriltag.so does not export image_u8_destroy; it is exactly these two frees.
	free(im->buf);
	free(im);
}

// A white grid one quiet-zone cell wider than the family's own drawing.
TagBitmap blankBitmap(const TagFamilyInfo& info, int coreCells, int coreBorderStart)
{
	TagBitmap bm;
	bm.cells = coreCells + 2;
	bm.borderStart = coreBorderStart + 1;
	bm.borderCells = info.borderCells;
	bm.pixels.assign(bm.cells * bm.cells, 255);
	return bm;
}

TagBitmap blankAprilTagBitmap(const TagFamilyInfo& info, const apriltag_family_t* fam)
{
	return blankBitmap(info, fam->total_width, (fam->total_width - fam->width_at_border) / 2);
}
}  // namespace

TagBitmap renderTagBitmap(const std::string& family, int id)
{
	const TagFamilyInfo& info = checkedFamily(family);
	if (id < 0 || id >= info.idCount)
		throw std::invalid_argument(
			"tag id " + std::to_string(id) + " is out of range for " + family + " (0.." +
			std::to_string(info.idCount - 1) + ")");
	if (info.system == TagSystem::AprilTag)
	{
		const apriltag_family_t* fam = drawingFamily(family);
		TagBitmap bm = blankAprilTagBitmap(info, fam);
		drawAprilTag(fam, id, bm);
		return bm;
	}
	const int cellsAcross = info.borderCells;  // data bits + black border
	cv::Mat img;
	cv::aruco::drawMarker(arucoDictionary(family), id, cellsAcross, img, 1);
	TagBitmap bm = blankBitmap(info, cellsAcross, 0);
	for (int r = 0; r < cellsAcross; r++)
		for (int c = 0; c < cellsAcross; c++)
			bm.pixels[(r + 1) * bm.cells + (c + 1)] = img.at<uint8_t>(r, c) > 127 ? 255 : 0;
	return bm;
}

namespace
{
// A code XOR code 0, as bytes: AprilTag's 64-bit word, or one byte per cell
// of an ArUco marker (at most 7 x 7).
using TurnedBits = std::array<uint8_t, 64>;

// Ids, ascending, each turning a bit that no id before it turned, until
// every bit some code turns is turned. `turnedOf(id)`: code `id` XOR code 0.
std::vector<int> firstIdsTurning(int codes, const std::function<TurnedBits(int id)>& turnedOf)
{
	TurnedBits ever{}, before{};
	for (int id = 1; id < codes; id++)
	{
		const TurnedBits t = turnedOf(id);
		for (size_t k = 0; k < ever.size(); k++) ever[k] |= t[k];
	}
	std::vector<int> ids;
	for (int id = 1; id < codes && before != ever; id++)
	{
		const TurnedBits t = turnedOf(id);
		bool fresh = false;
		for (size_t k = 0; k < before.size(); k++)
		{
			fresh = fresh || (t[k] & ~before[k]) != 0;
			before[k] |= t[k];
		}
		if (fresh) ids.push_back(id);
	}
	return ids;
}
}  // namespace

std::vector<int> idsTurningEveryCodeBit(const std::string& family)
{
	const TagFamilyInfo& info = checkedFamily(family);
	// The code words, not the drawings.
	if (info.system == TagSystem::AprilTag)
	{
		const apriltag_family_t* fam = drawingFamily(family);
		return firstIdsTurning(static_cast<int>(fam->ncodes), [&](int id) {
			TurnedBits t{};
			const uint64_t x = fam->codes[id] ^ fam->codes[0];
			for (size_t k = 0; k < 8; k++) t[k] = static_cast<uint8_t>((x >> (8 * k)) & 0xff);
			return t;
		});
	}
	const cv::Ptr<cv::aruco::Dictionary> dictionary = arucoDictionary(family);
	const auto bitsOf = [&](int id) {
		return cv::aruco::Dictionary::getBitsFromByteList(dictionary->bytesList.rowRange(id, id + 1),
														   dictionary->markerSize);
	};
	const cv::Mat first = bitsOf(0);
	return firstIdsTurning(info.idCount, [&](int id) {
		TurnedBits t{};
		const cv::Mat bits = bitsOf(id);
		for (int k = 0; k < static_cast<int>(first.total()) && k < static_cast<int>(t.size()); k++)
			t[static_cast<size_t>(k)] = bits.at<uint8_t>(k / first.cols, k % first.cols) != first.at<uint8_t>(k / first.cols, k % first.cols);
		return t;
	});
}

namespace
{
// Which of the square's symmetries map the code's bitmap onto itself.
struct BitmapSymmetries
{
	bool mirror;  // about an axis or a diagonal
	bool turn;    // a half turn (so also a quarter turn)
};

BitmapSymmetries symmetriesOf(const std::string& family, int id)
{
	const TagBitmap bm = renderTagBitmap(family, id);
	const int n = bm.cells;
	const auto at = [&](int r, int c) { return bm.pixels[static_cast<size_t>(r * n + c)]; };
	bool leftRight = true, upDown = true, diagonal = true, antiDiagonal = true, halfTurn = true;
	for (int r = 0; r < n; r++)
		for (int c = 0; c < n; c++)
		{
			leftRight = leftRight && at(r, c) == at(r, n - 1 - c);
			upDown = upDown && at(r, c) == at(n - 1 - r, c);
			diagonal = diagonal && at(r, c) == at(c, r);
			antiDiagonal = antiDiagonal && at(r, c) == at(n - 1 - c, n - 1 - r);
			halfTurn = halfTurn && at(r, c) == at(n - 1 - r, n - 1 - c);
		}
	// A bitmap a quarter turn maps onto itself is half-turn symmetric too.
	return {leftRight || upDown || diagonal || antiDiagonal, halfTurn};
}
}  // namespace

bool isOwnMirrorImage(const std::string& family, int id) { return symmetriesOf(family, id).mirror; }

bool isOwnTurnedImage(const std::string& family, int id) { return symmetriesOf(family, id).turn; }

void forEachTagBitmap(const std::string& family, const std::function<void(int id, const TagBitmap&)>& visit)
{
	const TagFamilyInfo& info = checkedFamily(family);
	if (info.system != TagSystem::AprilTag)
	{
		for (int id = 0; id < info.idCount; id++) visit(id, renderTagBitmap(family, id));
		return;
	}
	// One family lookup and one grid for all codes: a 65 k-code family drew
	// in 28 ms one renderTagBitmap() at a time (two grids and a copy each).
	const apriltag_family_t* fam = drawingFamily(family);
	TagBitmap bm = blankAprilTagBitmap(info, fam);
	for (int id = 0; id < info.idCount; id++)
	{
		drawAprilTag(fam, id, bm);
		visit(id, bm);
	}
}

const std::vector<TagCellBits>& codeCellBits(const std::string& family)
{
	checkedFamily(family);
	struct Table
	{
		std::once_flag made;
		std::vector<TagCellBits> codes;
	};
	Table* table = nullptr;
	{
		static std::mutex mutex;
		static std::map<std::string, std::unique_ptr<Table>> tables;
		std::lock_guard<std::mutex> lock(mutex);
		auto& slot = tables[family];
		if (!slot) slot = std::make_unique<Table>();
		table = slot.get();
	}
	std::call_once(table->made, [&] {
		table->codes.reserve(static_cast<size_t>(findFamily(family)->idCount));
		forEachTagBitmap(family, [&](int, const TagBitmap& bm) {
			if (bm.pixels.size() > TagCellBits().size())
				throw std::logic_error("tag grid larger than 256 cells: " + family);
			// 64 cells to a word, then the words into the bitset (it has no
			// word access of its own). A cell is 0 or 255, so a byte's top
			// bit is its colour: eight cells read as one little-endian word,
			// the multiply gathers their top bits into its top byte (cell j
			// at bit 56 + j), instead of a shift and an OR per cell.
			std::array<uint64_t, 4> words{};
			const uint8_t* cell = bm.pixels.data();
			const size_t n = bm.pixels.size();
			size_t k = 0;
			for (; k + 8 <= n; k += 8)
			{
				uint64_t eight = 0;
				for (unsigned b = 0; b < 8; b++) eight |= static_cast<uint64_t>(cell[k + b]) << (8 * b);
				words[k / 64] |= ((eight & 0x8080808080808080ull) * 0x0002040810204081ull >> 56) << (k % 64);
			}
			for (; k < n; k++) words[k / 64] |= static_cast<uint64_t>(cell[k] != 0) << (k % 64);
			TagCellBits bits;
			for (size_t w = words.size(); w-- > 0;) (bits <<= 64) |= TagCellBits(words[w]);
			table->codes.push_back(bits);
		});
	});
	return table->codes;
}

}  // namespace tagmap
