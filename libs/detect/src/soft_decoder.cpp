#include "tagmap/soft_decoder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <optional>

#include "tagmap/apriltag_families.h"
#include "tagmap/tag_family.h"

namespace tagmap
{
namespace
{
// Set bits of each byte value. __builtin_popcount is a libgcc call on the
// x86-64 baseline (no POPCNT instruction), and the correlation below takes
// one per byte of every code in every orientation.
constexpr std::array<uint8_t, 256> kBitsSet = [] {
	std::array<uint8_t, 256> t{};
	for (unsigned v = 1; v < 256; v++) t[v] = static_cast<uint8_t>(t[v / 2] + (v & 1));
	return t;
}();
}  // namespace

// Every code of a family over the cells that tell codes apart, packed.
struct SoftTagDecoder::FamilyCodes
{
	int cells = 0, borderStart = 0, borderCells = 0;
	/** The squares of cells [first, last) an outline of the tag may trace:
	 *  its border square; for a family whose border ring is white
	 *  (tagStandard*, tagCircle*: libapriltag's reversed border) also the
	 *  black ring just around it and the whole printed tag (its data cells
	 *  outside that ring join the ring's dark blob). */
	std::vector<std::pair<int, int>> outlines;
	bool whiteBorder = false;  // the border ring is white (more outlines than the border square)
	/** The fixed black ring: the border ring, or the ring around a white one. */
	int ringStart = 0, ringCells = 0;
	std::vector<int> informative;  // cells whose colour differs between codes
	/** idCount x whiteBytes: the codes' informative cells packed 8 to a
	 *  byte, bit i of byte b set when cell 8b + i is white. */
	std::vector<uint8_t> white;
	size_t whiteBytes = 0;
	std::vector<uint8_t> whiteCells;  // per code: its white informative cells
	std::vector<uint8_t> borderMask;  // 1: a border-ring cell (black), 2: a quiet-zone cell (white)
	/** Cells that are the same in every code (rings, quiet zone, fixed
	 *  corners), and whether each is white: the frame every code prints. */
	std::vector<int> frame;
	std::vector<float> frameWhite;
	int idCount = 0;
};

SoftTagDecoder::SoftTagDecoder(const std::vector<std::string>& families, SoftDecoderParams params)
	: params_(params), requested_(families)
{
	// A maximum-likelihood decoder always finds a nearest code; only codes
	// far apart make "nearest" mean "this one" (TagFamilyInfo::weak).
	for (const auto& name : searchFamilies(families))
		if (!findFamily(name)->weak()) families_.push_back(name);
}

SoftTagDecoder::~SoftTagDecoder() = default;

const SoftTagDecoder::FamilyCodes& SoftTagDecoder::codesOf(const std::string& family) const
{
	// One copy per process, whatever the number of decoders (threads): the
	// largest family's table is 0.5 MB.
	static std::mutex mutex;
	static std::map<std::string, std::unique_ptr<FamilyCodes>> cache;
	std::lock_guard<std::mutex> lock(mutex);
	auto& slot = cache[family];
	if (slot) return *slot;
	slot = std::make_unique<FamilyCodes>();
	FamilyCodes& fc = *slot;
	const TagFamilyInfo* info = findFamily(family);
	fc.idCount = info->idCount;
	const TagBitmap first = renderTagBitmap(family, 0);
	fc.cells = first.cells;
	fc.borderStart = first.borderStart;
	fc.borderCells = first.borderCells;
	fc.whiteBorder = first.at(fc.borderStart, fc.borderStart) != 0;
	fc.ringStart = fc.whiteBorder ? fc.borderStart - 1 : fc.borderStart;
	fc.ringCells = fc.whiteBorder ? fc.borderCells + 2 : fc.borderCells;
	fc.outlines = {{fc.borderStart, fc.borderStart + fc.borderCells}};
	if (fc.whiteBorder) fc.outlines.insert(fc.outlines.end(), {{fc.ringStart, fc.ringStart + fc.ringCells}, {1, fc.cells - 1}});
	const size_t all = static_cast<size_t>(fc.cells * fc.cells);
	// Every code's cells, one bit each, shared with the nearest-code search.
	const std::vector<TagCellBits>& codes = codeCellBits(family);
	// Cells that are the same in every code carry no information about the
	// id; leaving them out makes the correlation tell codes apart.
	TagCellBits whiteInSome, whiteInAll;
	whiteInAll.set();
	for (const TagCellBits& code : codes) whiteInSome |= code, whiteInAll &= code;
	for (size_t i = 0; i < all; i++)
		if (whiteInSome[i] && !whiteInAll[i]) fc.informative.push_back(static_cast<int>(i));
		else fc.frame.push_back(static_cast<int>(i)), fc.frameWhite.push_back(whiteInAll[i] ? 1.0f : 0.0f);
	const size_t n = fc.informative.size();
	fc.whiteBytes = (n + 7) / 8;
	fc.white.assign(fc.whiteBytes * static_cast<size_t>(fc.idCount), 0);
	for (int id = 0; id < fc.idCount; id++)
	{
		const TagCellBits& code = codes[static_cast<size_t>(id)];
		uint8_t* packed = &fc.white[static_cast<size_t>(id) * fc.whiteBytes];
		for (size_t j = 0; j < n; j++)
			packed[j / 8] |= static_cast<uint8_t>(code[static_cast<size_t>(fc.informative[j])] << (j % 8));
		int cellsWhite = 0;
		for (size_t byte = 0; byte < fc.whiteBytes; byte++) cellsWhite += kBitsSet[packed[byte]];
		fc.whiteCells.push_back(static_cast<uint8_t>(cellsWhite));
	}
	// Cells every code shares: the outline's ring is black, the quiet zone white.
	fc.borderMask.assign(all, 0);
	for (int r = 0; r < fc.cells; r++)
		for (int c = 0; c < fc.cells; c++)
		{
			const bool quiet = r == 0 || c == 0 || r == fc.cells - 1 || c == fc.cells - 1;
			const int b0 = fc.ringStart, b1 = fc.ringStart + fc.ringCells - 1;
			const bool ring = (r == b0 || r == b1 || c == b0 || c == b1) && r >= b0 && r <= b1 && c >= b0 && c <= b1;
			fc.borderMask[r * fc.cells + c] = quiet ? 2 : (ring && first.at(r, c) == 0 ? 1 : 0);
		}
	return fc;
}

// The best code and the best other code, by Pearson correlation.
struct SoftTagDecoder::BestCodes
{
	double best = -2, second = -2;
	int bestId = -1, bestOrder = -1;

	void offer(double r, int id, int order)
	{
		if (r > best)
		{
			if (!(bestId == id)) second = best;
			best = r;
			bestId = id;
			bestOrder = order;
		}
		else if (r > second && id != bestId)
			second = r;
	}
};

SoftTagDecoder::BestCodes SoftTagDecoder::correlate(const FamilyCodes& fc, const std::vector<float>& sample)
{
	// Pearson correlation over the measured cells S (all of them when
	// nothing is erased). With the data centred there (d), a code's
	// 0/1 cells c correlate as sum_S c d / sqrt((w - w^2 / |S|) sum_S d^2),
	// w its white cells in S: its mean over S drops out of the numerator.
	// Both sums come from tables over the code's packed bytes: for each
	// byte, the sum of d over every subset of its 8 cells (0 where not
	// measured), so a code costs a lookup per 8 cells, not a branch per cell.
	const size_t ni = fc.informative.size(), nb = fc.whiteBytes;
	BestCodes b;
	std::vector<double> d(nb * 8, 0.0), subsetSum(nb * 256);
	std::vector<uint8_t> measured(nb);
	std::vector<double> norm(ni + 1);
	for (int order = 0; order < 8; order++)
	{
		const std::vector<int>& perm = cellPermutation(fc.cells, order);
		std::fill(d.begin(), d.end(), 0.0);
		std::fill(measured.begin(), measured.end(), 0);
		double mean = 0;
		int count = 0;
		for (size_t j = 0; j < ni; j++)
		{
			const float v = sample[static_cast<size_t>(perm[fc.informative[j]])];
			if (std::isnan(v)) continue;
			d[j] = v;
			measured[j / 8] |= static_cast<uint8_t>(1u << (j % 8));
			mean += v;
			count++;
		}
		const double n = count;
		if (n < 2) continue;
		mean /= n;
		double ss = 0;
		for (size_t j = 0; j < ni; j++)
			if (measured[j / 8] >> (j % 8) & 1) d[j] -= mean, ss += d[j] * d[j];
		if (!(ss > 0)) continue;
		for (size_t byte = 0; byte < nb; byte++)
		{
			double* sums = &subsetSum[byte * 256];
			sums[0] = 0;
			for (unsigned m = 1; m < 256; m++)
				sums[m] = sums[m & (m - 1)] + d[byte * 8 + static_cast<unsigned>(__builtin_ctz(m))];
		}
		// The denominator depends on the code only through w: one root per
		// value of w, not one per code. With nothing erased, w is the
		// code's own count of white cells.
		for (size_t w = 0; w <= ni; w++)
		{
			const double spread = static_cast<double>(w) - static_cast<double>(w) * static_cast<double>(w) / n;
			norm[w] = spread > 0 ? std::sqrt(spread * ss) : 0.0;
		}
		const bool allMeasured = count == static_cast<int>(ni);
		for (int id = 0; id < fc.idCount; id++)
		{
			const uint8_t* white = &fc.white[id * nb];
			double dot = 0;
			int w = 0;
			for (size_t byte = 0; byte < nb; byte++) dot += subsetSum[byte * 256 + white[byte]];
			if (allMeasured) w = fc.whiteCells[static_cast<size_t>(id)];
			else
				for (size_t byte = 0; byte < nb; byte++) w += kBitsSet[white[byte] & measured[byte]];
			const double root = norm[static_cast<size_t>(w)];
			b.offer(root > 0 ? dot / root : 0.0, id, order);
		}
	}
	return b;
}

double SoftTagDecoder::frameCorrelation(const FamilyCodes& fc, const std::vector<float>& sample)
{
	// Pearson correlation of the measured frame cells with their colours.
	double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
	for (size_t j = 0; j < fc.frame.size(); j++)
	{
		const double v = sample[static_cast<size_t>(fc.frame[j])], c = fc.frameWhite[j];
		if (std::isnan(v)) continue;
		n++, sx += v, sy += c, sxx += v * v, syy += c * c, sxy += v * c;
	}
	if (n <= 2) return 0.0;
	const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
	return vx > 0 && vy > 0 ? (sxy - sx * sy / n) / std::sqrt(vx * vy) : 0.0;
}

std::optional<DecodedTag2D> SoftTagDecoder::read(const cv::Mat& gray8, const cv::Mat* measured, const Quad& q,
												  const std::string& family, const FamilyCodes& fc) const
{
	// The outline the frame fits best: a quad traces one square of the
	// tag, and the frame (the same in every code) tells which; the code is
	// then correlated there only.
	std::vector<float> sample;
	double bestFrame = params_.minCorrelation;
	std::pair<int, int> outline;
	for (const auto& [first, last] : fc.outlines)
	{
		std::vector<float> s = measured ? sampleMeasuredCells(gray8, *measured, q, fc.cells, first, last)
										: sampleCells(gray8, q, fc.cells, first, last);
		if (s.empty()) continue;
		// Shared cells first (the same in every orientation): a dark ring
		// inside a light quiet zone, or this is no tag of this family.
		double ring = 0, quiet = 0;
		int nr = 0, nq = 0;
		for (size_t i = 0; i < s.size(); i++)
		{
			if (std::isnan(s[i])) continue;
			if (fc.borderMask[i] == 1) ring += s[i], nr++;
			if (fc.borderMask[i] == 2) quiet += s[i], nq++;
		}
		if (nr == 0 || nq == 0 || ring / nr + 20 > quiet / nq) continue;
		// The whole frame, at least as clearly as a code must show
		// (minCorrelation): an outline placed a ring too far in or out
		// shows a ring of the wrong colour.
		const double frame = frameCorrelation(fc, s);
		if (frame < bestFrame) continue;
		bestFrame = frame, sample = std::move(s), outline = {first, last};
	}
	if (sample.empty()) return std::nullopt;
	const size_t ni = fc.informative.size();
	size_t erased = 0;
	for (int k : fc.informative) erased += std::isnan(sample[static_cast<size_t>(k)]);
	if (static_cast<double>(ni - erased) < params_.minMeasuredFraction * static_cast<double>(ni)) return std::nullopt;
	const BestCodes b = correlate(fc, sample);
	if (b.bestId < 0 || b.best < params_.minCorrelation || b.best - b.second < params_.minGap) return std::nullopt;
	DecodedTag2D d;
	d.family = reportedFamily(requested_, family, b.bestId);
	if (d.family.empty()) return std::nullopt;
	d.id = b.bestId;
	d.mirrored = b.bestOrder >= 4;
	// A read's corners are its border square's, whichever square the quad
	// outlined.
	d.corners = orderedCorners(
		gridSquareIn(q, outline.first, outline.second, fc.borderStart, fc.borderStart + fc.borderCells), b.bestOrder);
	d.margin = 100 * b.best;
	d.hamming = -1;  // not a bit decode
	return d;
}

std::vector<DecodedTag2D> SoftTagDecoder::decode(const cv::Mat& gray8, const std::vector<Quad>& quads,
												 const cv::Mat* measured, bool whiteBorders) const
{
	std::vector<DecodedTag2D> out;
	if (!params_.enabled || families_.empty()) return out;
	for (const Quad& q : quads)
		for (const auto& family : families_)
		{
			const FamilyCodes& fc = codesOf(family);
			if (fc.informative.empty() || (!whiteBorders && fc.whiteBorder)) continue;
			if (std::optional<DecodedTag2D> d = read(gray8, measured, q, family, fc)) out.push_back(std::move(*d));
		}
	dropRepeatedReads(out);
	return out;
}

}  // namespace tagmap
