#include "tagmap/sim/non_tag_interior.h"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

#include "tagmap/sim/rng.h"
#include "tagmap/tag_family.h"

namespace tagmap::sim
{
namespace
{
struct FamilyCodes
{
	int margin = 1;  // cells a square must differ by
	std::vector<std::vector<bool>> interiors;  // each code's n x n cells inside its border, true = black
};

// Every code of the families whose whole data sits inside a border of n + 2
// cells: outside it the bitmap has at most two white cells per side (our
// quiet cell, libapriltag's white ring); tagStandard* and tagCircle* print
// data rings there and have more.
std::vector<FamilyCodes> codesWithInterior(int n)
{
	std::vector<FamilyCodes> out;
	for (const TagFamilyInfo& f : supportedFamilies())
	{
		const TagBitmap first = renderTagBitmap(f.name, 0);
		if (first.borderCells != n + 2 || first.cells > first.borderCells + 4) continue;
		FamilyCodes fc;
		fc.margin = std::max(1, (f.minHamming + 1) / 2);
		for (int id = 0; id < f.idCount; id++)
		{
			const TagBitmap bm = id ? renderTagBitmap(f.name, id) : first;
			std::vector<bool> in(static_cast<size_t>(n) * n);
			const int o = bm.borderStart + 1;
			for (int r = 0; r < n; r++)
				for (int c = 0; c < n; c++) in[r * n + c] = bm.at(o + r, o + c) == 0;
			fc.interiors.push_back(std::move(in));
		}
		out.push_back(std::move(fc));
	}
	return out;
}

// Cell (r, c) of the interior seen in orientation k (0-3 rotations, +4 mirrored).
bool oriented(const std::vector<bool>& in, int n, int k, int r, int c)
{
	if (k >= 4) c = n - 1 - c;
	for (int i = 0; i < k % 4; i++)
	{
		const int t = r;
		r = c;
		c = n - 1 - t;
	}
	return in[r * n + c];
}

// Smallest (distance - margin) over the families' codes and orientations.
int slack(const std::vector<bool>& in, int n, const std::vector<FamilyCodes>& families, bool relative)
{
	int best = INT_MAX;
	for (const FamilyCodes& f : families)
		for (const auto& code : f.interiors)
			for (int k = 0; k < 8; k++)
			{
				int d = 0;
				for (int r = 0; r < n; r++)
					for (int c = 0; c < n; c++) d += oriented(in, n, k, r, c) != code[r * n + c];
				best = std::min(best, relative ? d - f.margin : d);
			}
	return best;
}
}  // namespace

std::vector<bool> nonTagInterior(int n, uint64_t seed)
{
	if (n < 3) throw std::runtime_error("a bordered square needs at least 3 x 3 interior cells");
	const auto families = codesWithInterior(n);
	Rng rng(streamSeed(seed, kStreamScene, 0xB0DE));
	std::bernoulli_distribution black(0.5);
	for (int attempt = 0; attempt < 1000; attempt++)
	{
		std::vector<bool> in(static_cast<size_t>(n) * n);
		for (size_t i = 0; i < in.size(); i++) in[i] = black(rng);
		if (slack(in, n, families, true) >= 0) return in;
	}
	throw std::runtime_error("no " + std::to_string(n) + "x" + std::to_string(n) +
							 " interior far enough from every code in 1000 draws");
}

int distanceToNearestCode(const std::vector<bool>& interior, int n, bool relativeToMargin)
{
	return slack(interior, n, codesWithInterior(n), relativeToMargin);
}

}  // namespace tagmap::sim
