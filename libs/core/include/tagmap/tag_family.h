// The fiducial families tagmap knows: their names (docs/RESULT_FORMAT.md),
// their canonical bitmaps (from libapriltag and OpenCV, never drawn by hand)
// and their geometry. Both the simulator (to print tags) and the decoder
// stage (to read them) go through this one registry.
#pragma once

#include <bitset>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tagmap
{
enum class TagSystem
{
	AprilTag,  // decoded by libapriltag
	ArUco  // decoded by OpenCV's aruco module
};

struct TagFamilyInfo
{
	std::string name;  // e.g. "tag36h11", "aruco_4x4_50"
	TagSystem system = TagSystem::AprilTag;
	int idCount = 0;  // number of valid ids
	/** Edge of the black border square, in bits (cells). The tag size `s`
	 *  is this edge in metres, so one cell is s / borderCells. */
	int borderCells = 0;
	/** Fewest bits in which two codes differ, any rotation considered. */
	int minHamming = 0;
	/** Codes this close (tag16h5, aruco_original, 4x4 and the larger 5x5
	 *  ArUco dictionaries) are easily imitated by posters, text and
	 *  shadows: they are read only when every bit is right, and never by
	 *  the soft (maximum-likelihood) decoder, which always finds a nearest
	 *  code. */
	bool weak() const { return minHamming < 7; }
};

/** True when the two readings name the same printed marker: the same family
 *  and id, or two ArUco dictionaries of one bit size (OpenCV's DICT_4X4_50
 *  is the first 50 markers of DICT_4X4_1000, and so on) and the same id.
 *  Without --family, the decoder names the smallest dictionary holding it. */
bool sameMarker(const std::string& familyA, int idA, const std::string& familyB, int idB);

/** The one name of a printed marker: for nested ArUco dictionaries, the
 *  smallest supported dictionary holding `id` (aruco_6x6_250 #3 and
 *  aruco_6x6_1000 #3 are both aruco_6x6_50 #3); any other family is its own
 *  name. "" when no dictionary of that bit size holds `id`. Things that must
 *  not depend on which dictionary a user asked for (beacon IDs) use it. */
std::string markerFamily(const std::string& family, int id);

/** The families a decoder has to search for `requested`: nested ArUco
 *  dictionaries of one bit size collapse to the largest requested one. */
std::vector<std::string> searchFamilies(const std::vector<std::string>& requested);

/** The name to report for `id` found while searching `searched`: itself,
 *  or for nested ArUco the smallest requested dictionary holding the id
 *  ("" when no requested dictionary holds it). */
std::string reportedFamily(const std::vector<std::string>& requested, const std::string& searched, int id);

/** Every family tagmap supports, AprilTag first. */
const std::vector<TagFamilyInfo>& supportedFamilies();

/** Family by name, or nullptr when unknown. */
const TagFamilyInfo* findFamily(const std::string& name);

/** "tag36h11, tag25h9, ..." for error messages. */
std::string supportedFamilyList();

/** Parses "tag36h11,aruco_4x4_50"; throws std::invalid_argument naming the
 *  unknown family and listing the valid ones. Empty input means all. */
std::vector<std::string> parseFamilyList(const std::string& commaSeparated);

/**
 * The printed pattern of one tag, upright (row 0 at the top), as a square
 * grid of cells. Cells are 0 (black ink) or 255 (white paper). The grid
 * includes one white quiet-zone cell around the family's own pattern, so
 * a tag printed from it always decodes. The border square that defines the
 * tag size spans cells [borderStart, borderStart + borderCells) on both axes.
 */
struct TagBitmap
{
	int cells = 0;  // grid is cells x cells
	int borderStart = 0;
	int borderCells = 0;
	std::vector<uint8_t> pixels;  // row-major, cells*cells

	uint8_t at(int row, int col) const { return pixels[row * cells + col]; }
	/** Cells from the grid's top-left corner to the tag's centre, along both
	 *  axes: tag-frame (x, y) in cells is grid column x + this, row -y + this
	 *  (grid rows run down, the tag frame's y up). */
	double centreInCells() const { return borderStart + borderCells / 2.0; }
};

/** Throws std::invalid_argument on an unknown family or out-of-range id. */
TagBitmap renderTagBitmap(const std::string& family, int id);

/** visit(id, bitmap) for every id of `family`, in id order: renderTagBitmap's
 *  bitmaps, drawn one after another into the same grid (valid during the
 *  call only). For tables of every code of a family (65 k codes for the
 *  largest). Throws std::invalid_argument on an unknown family. */
void forEachTagBitmap(const std::string& family, const std::function<void(int id, const TagBitmap&)>& visit);

/** A bitmap's cells as bits: cell k of TagBitmap::pixels at bit k, set
 *  where the cell is white (the largest grid, tagCircle49h12's with its
 *  quiet zone, has 13 x 13 cells). */
using TagCellBits = std::bitset<256>;

/** Every code of `family` as TagCellBits, in id order: made once per
 *  process on first use (from forEachTagBitmap()) and shared by every
 *  table that compares a read with all codes (the nearest-code search,
 *  the soft decoder's). Families are made independently, so two threads
 *  needing two families do not wait for each other. Throws
 *  std::invalid_argument on an unknown family. */
const std::vector<TagCellBits>& codeCellBits(const std::string& family);

/** The ids that, drawn beside id 0, show every cell in which the family's
 *  codes differ: for each bit of the code words, the first id that turns
 *  it (ascending, each once). A few dozen drawings instead of every code
 *  (65 k for the largest family); the order of the codes does not matter
 *  (aruco_original's highest id bits turn only at ids 256 and 512). Throws
 *  std::invalid_argument on an unknown family. */
std::vector<int> idsTurningEveryCodeBit(const std::string& family);

/** True when the code's bitmap is its own mirror image (about an axis or a
 *  diagonal): a read of it cannot tell the printed face from its back, so
 *  the side it faces is unknown from the code alone. No AprilTag code is;
 *  a few ArUco codes are (aruco_5x5_250 #129, aruco_6x6_1000 #622, 64 of
 *  aruco_original's). Throws std::invalid_argument on an unknown family or id. */
bool isOwnMirrorImage(const std::string& family, int id);

/** True when the code's bitmap is its own image under a half (or quarter)
 *  turn: a read of it cannot tell which corner is the first, so neither its
 *  vertex order nor its pose's turn about the normal can be known. Of the
 *  families here only aruco_original #1023 is. Throws std::invalid_argument
 *  on an unknown family or id. */
bool isOwnTurnedImage(const std::string& family, int id);

}  // namespace tagmap
