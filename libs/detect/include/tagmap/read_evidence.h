// Stage 5c: is a decoder's read a printed tag, or a pattern that happens to
// match a code? Each read is checked against the family's whole printed
// template, sampled cell by cell inside the decoded corners:
//  - chance: the probability that a random pattern matches *some* code of
//    the family, in any of its orientations, within the bits found wrong:
//        P = codes x orientations x sum_{k <= wrong} C(n, k) / 2^n
//    (n the code's bits, less those too grey to call). A read is accepted only when P is at most
//    chanceBudget / (families searched): enabling more families does not
//    let more false tags through, and a weak family (aruco_4x4_1000: 1000
//    codes of 16 bits, P = 0.12 for an exact read) is never accepted on a
//    pattern of unknown origin, however cleanly it reads.
//  - border: the black border ring must read black, cell by cell;
//  - quiet zone: the white margin around the tag must read white (a window
//    grid, a checkerboard or a code read into part of a larger pattern
//    continues there).
// Thresholds come from the read itself (halfway between the cells the
// template calls black and white), so no intensity scale is assumed.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tagmap/tag_decoder.h"
#include "tagmap/tag_family.h"
#include "tagmap/tag_quads.h"
#include "tagmap/verdict.h"

namespace tagmap
{
struct ReadEvidenceParams
{
	/** Largest chance-match probability of an accepted read, summed over
	 *  the families searched (a Bonferroni bound). With ~10^4 quads read
	 *  in a large cluttered map this allows ~0.1 false tags per map even if
	 *  clutter were random bits; it is far less structured than that.
	 *  A read rejected here and judged again on the grid its family's
	 *  frame places (candidate_decoder.cpp, placeByFrame()) has half of it there. */
	double chanceBudget = 1e-3;
	/** A code cell within this fraction of the black-white contrast of the
	 *  threshold is an erasure: it neither counts as wrong nor as evidence
	 *  (the chance is computed over the other cells). */
	double erasureBand = 0.15;
	/** Border-ring cells allowed to read white, as a fraction; more pass
	 *  when the code and the ring, counted together, are within the
	 *  chance budget. */
	double maxBorderErrorRate = 0.1;
	/** Quiet-zone cells allowed to read dark, as a fraction. */
	double maxQuietErrorRate = 0.15;
	/** assessMeasuredRead(): the fraction of the border ring's and of the
	 *  quiet zone's cells that must have been scanned. */
	double minMeasuredFrame = 0.5;
};

struct ReadEvidence
{
	int codeBits = 0;  // cells that differ between the family's codes
	int bitErrors = 0;  // code cells read the other colour
	int erasures = 0;  // code cells too close to the threshold to call
	int borderErrors = 0, borderCells = 0;  // black ring cells read white
	int quietErrors = 0, quietCells = 0;  // white margin cells read dark
	double chance = 1;  // probability of a match this good by chance
	/** The cell values judged (row-major over the family's whole grid, as
	 *  sampleCells()); empty when the grid left the image. */
	std::vector<float> cells;
	/** Nothing when accepted, else Verdict::ByChance, NoBorder or
	 *  NoQuietZone; GridOffImage when the grid left the image (no cells). */
	std::optional<Verdict> rejection;
};

/** The evidence of `read` on the image it was read from. `orientations`:
 *  how many ways a quad was tried (4 rotations, x2 when both sides are
 *  read); `searched`: the families the decoder searched (searchFamilies():
 *  their number divides the budget, and a nested ArUco read counts the
 *  codes of the dictionary actually searched). */
ReadEvidence assessRead(const cv::Mat& gray8, const DecodedTag2D& read, int orientations,
						const std::vector<std::string>& searched, const ReadEvidenceParams& p);

/** assessRead() with the cells nothing was scanned in erased
 *  (sampleMeasuredCells()). A read whose border ring or quiet zone is
 *  mostly erased shows no frame to judge: rejected (NoBorder,
 *  NoQuietZone) unless minMeasuredFrame of each was measured. */
ReadEvidence assessMeasuredRead(const cv::Mat& gray8, const cv::Mat& measured, const DecodedTag2D& read,
								int orientations, const std::vector<std::string>& searched, const ReadEvidenceParams& p);

/** The same judgement on the cell values of a read of `family`:`id`
 *  (row-major over its whole grid, as sampleCells()); NaN marks a cell
 *  nothing measured, an erasure (code_in_points.h). `decoderHamming`: the
 *  bit decoder's own count of wrong bits, or -1; when it makes the read
 *  less likely by chance it is used, over the measured code cells. */
ReadEvidence judgeCells(const std::vector<float>& cells, const std::string& family, int id, int decoderHamming,
						int orientations, const std::vector<std::string>& searched, const ReadEvidenceParams& p);

/** Hamming distances, over the code cells a read shows clearly (as
 *  judgeCells() calls them: NaN or within the erasure band are left out),
 *  from the read to its own code and to the nearest other code of the
 *  family in any of `orientations` orientations (4 rotations, x2 mirrored;
 *  its own code turned counts as other, a code that turned is its own code
 *  cell for cell does not). A read nearer another code than its own, or as
 *  near, is not a read of it. */
struct CodeDistances
{
	int toOwn = 0;
	int toNearestOther = 0;
	int nearestOtherId = -1;
};
CodeDistances codeDistances(const std::vector<float>& cells, const std::string& family, int id, int orientations,
							const ReadEvidenceParams& p);

/** The families of `requested` (in order) that a read can be accepted in:
 *  a read shows at most every code bit right and none erased, so a family
 *  whose exact read is already more likely than the budget by chance
 *  (aruco_4x4_1000: 0.12, aruco_original and 5x5_1000: 2.4e-4,
 *  tagCircle21h7: 1.4e-4, tag16h5: 3.7e-3, against 7.7e-5 with every family
 *  searched) would only be decoded to be rejected as by_chance. The budget
 *  stays split over every family searched: the rule does not change. */
std::vector<std::string> acceptableFamilies(const std::vector<std::string>& requested, int orientations,
											const ReadEvidenceParams& p);

/** The fewest cells a read of any of `families` must see the colour of:
 *  its code cells and its black border ring (49 for tag25h9 and the 5x5
 *  ArUco dictionaries, 64 for tag36h11). A point measures one footprint,
 *  so an image rendered from fewer points than that has cells no point
 *  measured, and what decodes there was interpolated, not read. 0 when
 *  `families` is empty. */
int fewestCellsToRead(const std::vector<std::string>& families);

/** Whether any read of one of `families` on quad `q` could pass, told
 *  from the quad's cells before a decoder runs. Inside its border ring a
 *  tag shows code cells of both colours: no code of any family is one
 *  colour throughout (`ReadEvidence.NoCodeIsOneColourThroughout`), and a
 *  read needs most code cells clearly right. A window pane (dark inside
 *  a light frame) or a light panel in a dark frame shows one colour only.
 *  Colours are judged as a read's are: halfway between the family's fixed
 *  black ring and white quiet zone, cells within the erasure band of it
 *  count for neither. */
bool quadCanShowACode(const cv::Mat& gray8, const Quad& q, const std::vector<std::string>& families,
					  const ReadEvidenceParams& p);

/** What every code of `family` prints alike: its grid (as
 *  renderTagBitmap()) with the border ring black, the quiet zone white and
 *  every code cell mid-grey (128). A grid placed by it favours no code. */
TagBitmap frameBitmap(const std::string& family);

/** Probability that a uniformly random n-bit pattern lies within `wrong`
 *  bits of one of `codes` codes in one of `orientations` orientations. */
double chanceMatchProbability(int codes, int n, int wrong, int orientations);

}  // namespace tagmap
