#include "tagmap/candidate_filter.h"

#include <cmath>

namespace tagmap
{
std::string rejectCandidate(const OrientedBox& box, double band, double noise, const CandidateFilterParams& p)
{
	const double l = box.extent.x(), w = box.extent.y(), h = box.extent.z();
	const double aMin = p.tagSize > 0 ? p.tagSize : p.minTagSize;
	const double aMax = p.tagSize > 0 ? p.tagSize : p.maxTagSize;
	// Paper's criterion 1 in the tag plane: a*sqrt(2) <= diag <= 2a; the
	// kept edge band widens the box by up to `band` on every side.
	const double diag = std::hypot(l, w);
	if (diag < std::sqrt(2.0) * aMin * (1 - p.shortfall) || diag > p.maxOversize * 2 * (aMax + 2 * band)) return "size";
	if (w <= 0 || l / w > p.maxAspect) return "squareness";
	if (h > p.maxFlatness * w + 2 * noise) return "not_flat";
	return "";
}

}  // namespace tagmap
