#include "tagmap/soft_decoder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>

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
	std::vector<int> informative;  // cells whose colour differs between codes
	/** idCount x whiteBytes: the codes' informative cells packed 8 to a
	 *  byte, bit i of byte b set when cell 8b + i is white. */
	std::vector<uint8_t> white;
	size_t whiteBytes = 0;
	std::vector<uint8_t> borderMask;  // 1: a border-ring cell (black), 2: a quiet-zone cell (white)
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
	const size_t n = fc.informative.size();
	fc.whiteBytes = (n + 7) / 8;
	fc.white.assign(fc.whiteBytes * static_cast<size_t>(fc.idCount), 0);
	for (int id = 0; id < fc.idCount; id++)
	{
		const TagCellBits& code = codes[static_cast<size_t>(id)];
		uint8_t* packed = &fc.white[static_cast<size_t>(id) * fc.whiteBytes];
		for (size_t j = 0; j < n; j++)
			packed[j / 8] |= static_cast<uint8_t>(code[static_cast<size_t>(fc.informative[j])] << (j % 8));
	}
	// Cells every code shares: the border ring is black, the quiet zone white.
	fc.borderMask.assign(all, 0);
	for (int r = 0; r < fc.cells; r++)
		for (int c = 0; c < fc.cells; c++)
		{
			const bool quiet = r == 0 || c == 0 || r == fc.cells - 1 || c == fc.cells - 1;
			const int b0 = fc.borderStart, b1 = fc.borderStart + fc.borderCells - 1;
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
		for (int id = 0; id < fc.idCount; id++)
		{
			const uint8_t* white = &fc.white[id * nb];
			double dot = 0;
			int w = 0;
			for (size_t byte = 0; byte < nb; byte++)
			{
				dot += subsetSum[byte * 256 + white[byte]];
				w += kBitsSet[white[byte] & measured[byte]];
			}
			const double spread = w - static_cast<double>(w) * w / n;
			b.offer(spread > 0 ? dot / std::sqrt(spread * ss) : 0.0, id, order);
		}
	}
	return b;
}

std::vector<DecodedTag2D> SoftTagDecoder::decode(const cv::Mat& gray8, const std::vector<Quad>& quads,
												 const cv::Mat* measured) const
{
	std::vector<DecodedTag2D> out;
	if (!params_.enabled || families_.empty()) return out;
	for (const Quad& q : quads)
	{
		for (const auto& family : families_)
		{
			const FamilyCodes& fc = codesOf(family);
			const size_t ni = fc.informative.size();
			if (ni == 0) continue;
			const std::vector<float> sample =
				measured ? sampleMeasuredCells(gray8, *measured, q, fc.cells, fc.borderStart, fc.borderStart + fc.borderCells)
						 : sampleCells(gray8, q, fc.cells, fc.borderStart, fc.borderStart + fc.borderCells);
			if (sample.empty()) continue;
			// Shared cells first (the same in every orientation): a dark ring
			// inside a light quiet zone, or this is no tag of this family.
			double ring = 0, quiet = 0;
			int nr = 0, nq = 0;
			for (size_t i = 0; i < sample.size(); i++)
			{
				if (std::isnan(sample[i])) continue;
				if (fc.borderMask[i] == 1) ring += sample[i], nr++;
				if (fc.borderMask[i] == 2) quiet += sample[i], nq++;
			}
			if (nr == 0 || nq == 0 || ring / nr + 20 > quiet / nq) continue;
			size_t erased = 0;
			for (int k : fc.informative) erased += std::isnan(sample[static_cast<size_t>(k)]);
			if (static_cast<double>(ni - erased) < params_.minMeasuredFraction * static_cast<double>(ni)) continue;
			const BestCodes b = correlate(fc, sample);
			if (b.bestId < 0 || b.best < params_.minCorrelation || b.best - b.second < params_.minGap) continue;
			DecodedTag2D d;
			d.family = reportedFamily(requested_, family, b.bestId);
			if (d.family.empty()) continue;
			d.id = b.bestId;
			d.mirrored = b.bestOrder >= 4;
			d.corners = orderedCorners(q, b.bestOrder);
			d.margin = 100 * b.best;
			d.hamming = -1;  // not a bit decode
			out.push_back(d);
		}
	}
	dropRepeatedReads(out);
	return out;
}

}  // namespace tagmap
