#include "tagmap/decode_schedule.h"

#include <algorithm>
#include <numeric>

#include "disjoint_sets.h"

namespace tagmap
{
std::vector<std::vector<size_t>> concentricBoxGroups(const std::vector<OrientedBox>& boxes)
{
	const size_t n = boxes.size();
	// Sweep along x: a pair's centres are closer than half the narrower
	// width, so the one further left reaches the other within half its own.
	std::vector<size_t> byX(n);
	std::iota(byX.begin(), byX.end(), size_t{0});
	std::sort(byX.begin(), byX.end(), [&](size_t a, size_t b) { return boxes[a].center.x() < boxes[b].center.x(); });
	const auto width = [&](size_t i) { return std::min(boxes[i].extent.x(), boxes[i].extent.y()); };
	detail::DisjointSets sets(n);
	for (size_t s = 0; s < n; s++)
	{
		const size_t i = byX[s];
		for (size_t t = s + 1; t < n && boxes[byX[t]].center.x() - boxes[i].center.x() < 0.5 * width(i); t++)
		{
			const size_t j = byX[t];
			if ((boxes[i].center - boxes[j].center).norm() < 0.5 * std::min(width(i), width(j)))
				sets.unite(static_cast<uint32_t>(i), static_cast<uint32_t>(j));
		}
	}
	std::vector<std::vector<size_t>> groups;
	std::vector<size_t> groupOfRoot(n, n);
	for (size_t i = 0; i < n; i++)  // ascending: a root comes first in its group
	{
		const size_t r = sets.find(static_cast<uint32_t>(i));
		if (groupOfRoot[r] == n)
		{
			groupOfRoot[r] = groups.size();
			groups.emplace_back();
		}
		groups[groupOfRoot[r]].push_back(i);
	}
	return groups;
}

bool onDecodedTag(const Eigen::Vector3d& point, const TagDetection& tag)
{
	return (point - tag.position()).norm() < 0.5 * tag.size;
}

}  // namespace tagmap
