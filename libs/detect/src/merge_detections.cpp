#include "tagmap/merge_detections.h"

#include <algorithm>
#include <tuple>

namespace tagmap
{
namespace
{
// Better support first: pattern fit, then points, then decoder margin.
bool better(const TagDetection& a, const TagDetection& b)
{
	return std::make_tuple(a.patternFit, a.pointsUsed, a.decodeMargin) >
		   std::make_tuple(b.patternFit, b.pointsUsed, b.decodeMargin);
}
}  // namespace

std::vector<TagDetection> mergeDetections(std::vector<TagDetection> found)
{
	std::stable_sort(found.begin(), found.end(), better);
	std::vector<TagDetection> kept;
	for (auto& d : found)
	{
		const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const TagDetection& k) {
			return (k.position() - d.position()).norm() < 0.5 * std::max(k.size, d.size);
		});
		if (!duplicate) kept.push_back(std::move(d));
	}
	std::sort(kept.begin(), kept.end(), [](const TagDetection& a, const TagDetection& b) {
		return std::make_tuple(a.family, a.id, a.position().x(), a.position().y(), a.position().z()) <
			   std::make_tuple(b.family, b.id, b.position().x(), b.position().y(), b.position().z());
	});
	return kept;
}

}  // namespace tagmap
