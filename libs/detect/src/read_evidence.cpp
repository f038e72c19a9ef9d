#include "tagmap/read_evidence.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "tagmap/tag_family.h"
#include "tagmap/tag_quads.h"

namespace tagmap
{
namespace
{
/** Which cells of a family's grid carry the code (differ between ids) and
 *  which are fixed black (border ring) or fixed white (quiet zone). */
struct CellRoles
{
	std::vector<uint8_t> role;  // 0 code, 1 fixed black, 2 fixed white
	int codeBits = 0;
	int blackCells = 0, whiteCells = 0;  // fixed: the border ring's, the quiet zone's
	int cells = 0, borderStart = 0, borderCells = 0;  // the grid, as TagBitmap's

	bool sameLayout(const CellRoles& o) const
	{
		return cells == o.cells && borderStart == o.borderStart && borderCells == o.borderCells && role == o.role;
	}
};

const CellRoles& rolesOf(const std::string& family)
{
	static std::mutex mutex;
	static std::map<std::string, std::unique_ptr<CellRoles>> cache;
	std::lock_guard<std::mutex> lock(mutex);
	auto& slot = cache[family];
	if (slot) return *slot;
	slot = std::make_unique<CellRoles>();
	const TagBitmap first = renderTagBitmap(family, 0);
	slot->cells = first.cells, slot->borderStart = first.borderStart, slot->borderCells = first.borderCells;
	// A code cell is one in which the family's codes differ.
	std::vector<bool> varies(first.pixels.size(), false);
	for (const int id : idsTurningEveryCodeBit(family))
	{
		const TagBitmap b = renderTagBitmap(family, id);
		for (size_t k = 0; k < varies.size(); k++) varies[k] = varies[k] || b.pixels[k] != first.pixels[k];
	}
	slot->role.resize(varies.size());
	for (size_t k = 0; k < varies.size(); k++)
	{
		slot->role[k] = varies[k] ? 0 : (first.pixels[k] ? 2 : 1);
		slot->codeBits += varies[k];
		slot->blackCells += slot->role[k] == 1;
		slot->whiteCells += slot->role[k] == 2;
	}
	return *slot;
}
// The codes a read of `family` competes with: a nested ArUco read counts
// the codes of the largest dictionary searched.
int codesJudged(const std::string& family, const std::vector<std::string>& searched)
{
	int codes = findFamily(family)->idCount;
	for (const std::string& f : searched)
		if (sameMarker(f, 0, family, 0)) codes = std::max(codes, findFamily(f)->idCount);
	return codes;
}

double budgetPerFamily(const std::vector<std::string>& searched, const ReadEvidenceParams& p)
{
	return p.chanceBudget / static_cast<double>(std::max<size_t>(searched.size(), 1));
}

// Where a read's cell values turn from black to white: halfway between the
// cells its code calls black and those it calls white (no intensity scale
// assumed), and the band around it too close to call. `ok` false when a
// colour has no measured cell.
struct CellThreshold
{
	double threshold = 0, unsure = 0;
	bool ok = false;
};

CellThreshold thresholdOf(const std::vector<float>& sample, const TagBitmap& bm, const ReadEvidenceParams& p)
{
	CellThreshold th;
	double black = 0, white = 0;
	int nb = 0, nw = 0;
	for (size_t k = 0; k < sample.size(); k++)
		if (!std::isnan(sample[k])) (bm.pixels[k] ? white : black) += sample[k], (bm.pixels[k] ? nw : nb)++;
	if (nb == 0 || nw == 0) return th;
	black /= nb;
	white /= nw;
	th.threshold = 0.5 * (black + white);
	th.unsure = p.erasureBand * (white - black);
	th.ok = true;
	return th;
}

// The verdict on counted evidence: chance first, then the border ring, then
// the quiet zone. `ringChance`: the chance of a match as good over the code
// cells and the ring's together (a ring cell read white an error like a
// wrong bit).
ReadEvidence withRejection(ReadEvidence e, double ringChance, const std::vector<std::string>& searched,
						   const ReadEvidenceParams& p)
{
	const double budget = budgetPerFamily(searched, p);
	e.rejection = Verdict::ByChance;
	if (e.chance > budget) return e;
	// A ring with more white cells than the rate allows (a grid, a larger
	// pattern, or a tag at the edge of the scan) still stands when the code
	// and the ring, counted together, are beyond chance: a code read
	// exactly on 36 cells outweighs a quarter of its ring washed out.
	e.rejection = Verdict::NoBorder;
	if (e.borderErrors > p.maxBorderErrorRate * e.borderCells && ringChance > budget) return e;
	e.rejection = Verdict::NoQuietZone;
	if (e.quietErrors > p.maxQuietErrorRate * e.quietCells) return e;
	e.rejection.reset();
	return e;
}
}  // namespace

std::vector<std::string> acceptableFamilies(const std::vector<std::string>& requested, int orientations,
											const ReadEvidenceParams& p)
{
	const std::vector<std::string> searched = searchFamilies(requested);
	std::vector<std::string> out;
	for (const std::string& f : requested)
		if (chanceMatchProbability(codesJudged(f, searched), rolesOf(f).codeBits, 0, orientations) <=
			budgetPerFamily(searched, p))
			out.push_back(f);
	return out;
}

int fewestCellsToRead(const std::vector<std::string>& families)
{
	int fewest = 0;
	for (const std::string& f : families)
	{
		const CellRoles& roles = rolesOf(f);
		const int cells = static_cast<int>(std::count_if(roles.role.begin(), roles.role.end(), [](uint8_t r) { return r != 2; }));
		if (fewest == 0 || cells < fewest) fewest = cells;
	}
	return fewest;
}

bool quadCanShowACode(const cv::Mat& gray8, const Quad& q, const std::vector<std::string>& families,
					  const ReadEvidenceParams& p)
{
	std::vector<const CellRoles*> judged;  // families sharing a layout are sampled once
	for (const std::string& f : families)
	{
		const CellRoles& roles = rolesOf(f);
		if (std::any_of(judged.begin(), judged.end(), [&](const CellRoles* r) { return r->sameLayout(roles); }))
			continue;
		judged.push_back(&roles);
		const std::vector<float> cells =
			sampleCells(gray8, q, roles.cells, roles.borderStart, roles.borderStart + roles.borderCells);
		if (cells.empty()) continue;  // the grid leaves the image: assessRead() rejects such a read too
		double black = 0, white = 0;
		int nb = 0, nw = 0;
		for (size_t k = 0; k < cells.size(); k++)
			if (roles.role[k] == 1) black += cells[k], nb++;
			else if (roles.role[k] == 2) white += cells[k], nw++;
		if (nb == 0 || nw == 0) return true;
		black /= nb, white /= nw;
		if (white <= black) continue;  // no dark ring in a light margin
		const double threshold = 0.5 * (black + white), unsure = p.erasureBand * (white - black);
		bool someWhite = false, someBlack = false;
		for (size_t k = 0; k < cells.size(); k++)
			if (roles.role[k] == 0)
			{
				someWhite = someWhite || cells[k] > threshold + unsure;
				someBlack = someBlack || cells[k] < threshold - unsure;
			}
		if (someWhite && someBlack) return true;
	}
	return false;
}

TagBitmap frameBitmap(const std::string& family)
{
	const CellRoles& roles = rolesOf(family);
	TagBitmap bm;
	bm.cells = roles.cells;
	bm.borderStart = roles.borderStart;
	bm.borderCells = roles.borderCells;
	bm.pixels.resize(roles.role.size());
	for (size_t k = 0; k < roles.role.size(); k++) bm.pixels[k] = roles.role[k] == 1 ? 0 : (roles.role[k] == 2 ? 255 : 128);
	return bm;
}

double chanceMatchProbability(int codes, int n, int wrong, int orientations)
{
	// sum_{k<=wrong} C(n,k) / 2^n: n reaches about 100 cells (a code and its ring).
	double ball = 0, binom = 1;
	for (int k = 0; k <= wrong && k <= n; k++)
	{
		ball += binom;
		binom = binom * (n - k) / (k + 1);
	}
	return std::min(1.0, static_cast<double>(codes) * orientations * ball * std::pow(2.0, -n));
}

ReadEvidence judgeCells(const std::vector<float>& sample, const std::string& family, int id, int decoderHamming,
						int orientations, const std::vector<std::string>& searched, const ReadEvidenceParams& p)
{
	ReadEvidence e;
	const CellRoles& roles = rolesOf(family);
	e.codeBits = roles.codeBits;
	e.rejection = Verdict::ByChance;
	const TagBitmap bm = renderTagBitmap(family, id);
	if (sample.size() != bm.pixels.size()) return e;
	const CellThreshold th = thresholdOf(sample, bm, p);
	if (!th.ok) return e;
	const double threshold = th.threshold, unsure = th.unsure;
	int unmeasured = 0;  // code cells with no value at all
	for (size_t k = 0; k < sample.size(); k++)
	{
		// An unmeasured cell is no evidence either way: an erasure of a code
		// cell, and not counted among the border's or the margin's cells.
		const bool measured = !std::isnan(sample[k]);
		const bool readWhite = sample[k] > threshold, isWhite = bm.pixels[k] != 0;
		switch (roles.role[k])
		{
			case 0:
				// A cell this close to the threshold (blur, a sparse cell) is
				// no evidence either way: an erasure, not an error.
				unmeasured += !measured;
				if (!measured || std::abs(sample[k] - threshold) < unsure) e.erasures++;
				else e.bitErrors += readWhite != isWhite;
				break;
			case 1: e.borderCells += measured, e.borderErrors += measured && readWhite; break;
			default: e.quietCells += measured, e.quietErrors += measured && !readWhite; break;
		}
	}
	// Erased cells match anything: only the others can tell a code from chance.
	const int codes = codesJudged(family, searched);
	e.chance = chanceMatchProbability(codes, e.codeBits - e.erasures, e.bitErrors, orientations);
	// A bit decoder's own count may be the better one: it reads each cell
	// from the edges it found, our samples come from the cell middles. Its
	// errors may all lie among the measured cells.
	const int measuredBits = e.codeBits - unmeasured;
	if (decoderHamming >= 0 && chanceMatchProbability(codes, measuredBits, decoderHamming, orientations) < e.chance)
	{
		e.bitErrors = decoderHamming, e.erasures = unmeasured;
		e.chance = chanceMatchProbability(codes, measuredBits, decoderHamming, orientations);
	}
	const double ringChance = chanceMatchProbability(codes, e.codeBits - e.erasures + e.borderCells,
													 e.bitErrors + e.borderErrors, orientations);
	return withRejection(e, ringChance, searched, p);
}

CodeDistances codeDistances(const std::vector<float>& cells, const std::string& family, int id, int orientations,
							const ReadEvidenceParams& p)
{
	CodeDistances d;
	const TagBitmap bm = renderTagBitmap(family, id);
	if (cells.size() != bm.pixels.size()) return d;
	const CellThreshold th = thresholdOf(cells, bm, p);
	if (!th.ok) return d;
	// The code cells the read shows clearly, with their colours.
	const CellRoles& roles = rolesOf(family);
	std::vector<uint8_t> clear(cells.size(), 0), white(cells.size(), 0);
	int clearCount = 0;
	for (size_t k = 0; k < cells.size(); k++)
		if (roles.role[k] == 0 && !std::isnan(cells[k]) && std::abs(cells[k] - th.threshold) >= th.unsure)
		{
			clear[k] = 1, white[k] = cells[k] > th.threshold, clearCount++;
			d.toOwn += white[k] != (bm.pixels[k] != 0);
		}
	// Every other code in every orientation: the read in orientation o shows
	// cell perm[j] of the read where the code has cell j. The read is turned
	// into each code's cell order once per orientation (its clear cells, their
	// colours, its code cells and its own code's colours there), so a code's
	// distance is a few XORs and popcounts.
	d.toNearestOther = clearCount + 1;
	const std::vector<TagCellBits>& codes = codeCellBits(family);
	for (int o = 0; o < orientations; o++)
	{
		const std::vector<int>& perm = cellPermutation(bm.cells, o);
		TagCellBits clearAt, whiteAt, codeAt, ownAt;
		for (size_t j = 0; j < perm.size(); j++)
		{
			const size_t k = static_cast<size_t>(perm[j]);
			clearAt[j] = clear[k] != 0;
			whiteAt[j] = white[k] != 0;
			codeAt[j] = roles.role[k] == 0;
			ownAt[j] = bm.pixels[k] != 0;
		}
		for (size_t other = 0; other < codes.size(); other++)
		{
			if (static_cast<int>(other) == id && o == 0) continue;
			const int dist = static_cast<int>(((codes[other] ^ whiteAt) & clearAt).count());
			if (dist >= d.toNearestOther) continue;
			// A code that, turned, is the read's own code cell for cell (the
			// original ArUco dictionary has such pairs) is no rival: no read
			// can tell them apart, and the decoder's choice is the family's.
			const bool same = ((codes[other] ^ ownAt) & codeAt).none();
			if (!same) d.toNearestOther = dist, d.nearestOtherId = static_cast<int>(other);
		}
	}
	return d;
}

namespace
{
// A read's cells sampled inside its corners (in vertex order, so upright),
// from every pixel or from the `measured` ones only, and judged.
ReadEvidence judgeSampledRead(const cv::Mat& gray8, const cv::Mat* measured, const DecodedTag2D& read,
							  int orientations, const std::vector<std::string>& searched, const ReadEvidenceParams& p)
{
	const CellRoles& grid = rolesOf(read.family);
	const int first = grid.borderStart, last = grid.borderStart + grid.borderCells;
	std::vector<float> cells = measured ? sampleMeasuredCells(gray8, *measured, read.corners, grid.cells, first, last)
										: sampleCells(gray8, read.corners, grid.cells, first, last);
	ReadEvidence e = judgeCells(cells, read.family, read.id, read.hamming, orientations, searched, p);
	if (cells.empty()) e.rejection = Verdict::GridOffImage;  // nothing sampled: no chance to judge
	e.cells = std::move(cells);
	return e;
}
}  // namespace

ReadEvidence assessRead(const cv::Mat& gray8, const DecodedTag2D& read, int orientations,
						const std::vector<std::string>& searched, const ReadEvidenceParams& p)
{
	return judgeSampledRead(gray8, nullptr, read, orientations, searched, p);
}

ReadEvidence assessMeasuredRead(const cv::Mat& gray8, const cv::Mat& measured, const DecodedTag2D& read,
								int orientations, const std::vector<std::string>& searched, const ReadEvidenceParams& p)
{
	ReadEvidence e = judgeSampledRead(gray8, &measured, read, orientations, searched, p);
	if (e.rejection || e.cells.empty()) return e;
	const CellRoles& roles = rolesOf(read.family);
	if (e.borderCells < p.minMeasuredFrame * roles.blackCells) e.rejection = Verdict::NoBorder;
	else if (e.quietCells < p.minMeasuredFrame * roles.whiteCells) e.rejection = Verdict::NoQuietZone;
	return e;
}

}  // namespace tagmap
