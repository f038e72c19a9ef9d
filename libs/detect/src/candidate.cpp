#include "candidate.h"

#include <algorithm>

#include "tagmap/tag_family.h"

namespace tagmap::detail
{
CandidateFilterParams filterParams(const PipelineParams& p)
{
	CandidateFilterParams cf = p.candidates;
	if (p.tagSize > 0) cf.tagSize = p.tagSize;
	return cf;
}

BorderCellsRange borderCellsAcross(const std::vector<std::string>& families)
{
	BorderCellsRange r;
	for (const std::string& f : families)
	{
		const int cells = findFamily(f)->borderCells;
		r.fewest = r.fewest > 0 ? std::min(r.fewest, cells) : cells;
		r.most = std::max(r.most, cells);
	}
	return r;
}

std::vector<std::string> familiesAsked(const PipelineParams& p)
{
	return p.families.empty() ? parseFamilyList("") : p.families;
}

double smallestSideAsked(const PipelineParams& p)
{
	return p.tagSize > 0 ? p.tagSize * (1 - kGivenSizeTolerance) : p.candidates.minTagSize;
}

double smallestReportableCell(const PipelineParams& p, const std::vector<std::string>& families)
{
	const int most = borderCellsAcross(families).most;
	return most > 0 ? smallestSideAsked(p) / most : 0;
}

int readOrientations(const PipelineParams& p) { return p.decoder.tryMirrored ? 8 : 4; }

}  // namespace tagmap::detail
