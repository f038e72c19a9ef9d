#include "tagmap/decode_schedule.h"

#include <algorithm>
#include <numeric>

namespace tagmap
{
namespace
{
// Union-find over box indices; a root is its group's smallest index.
struct Groups
{
	std::vector<size_t> parent;
	explicit Groups(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), size_t{0}); }
	size_t root(size_t i)
	{
		while (parent[i] != i) i = parent[i] = parent[parent[i]];
		return i;
	}
	void join(size_t a, size_t b)
	{
		a = root(a), b = root(b);
		if (a != b) parent[std::max(a, b)] = std::min(a, b);
	}
};
}  // namespace

std::vector<std::vector<size_t>> overlappingBoxGroups(const std::vector<OrientedBox>& boxes)
{
	const size_t n = boxes.size();
	std::vector<Eigen::Vector3d> lo(n), hi(n);
	for (size_t i = 0; i < n; i++)
	{
		const Eigen::Vector3d reach = boxes[i].axes.cwiseAbs() * (0.5 * boxes[i].extent);
		lo[i] = boxes[i].center - reach;
		hi[i] = boxes[i].center + reach;
	}
	// Sweep along x: only boxes that start before one ends can overlap it.
	std::vector<size_t> byStart(n);
	std::iota(byStart.begin(), byStart.end(), size_t{0});
	std::sort(byStart.begin(), byStart.end(), [&](size_t a, size_t b) { return lo[a].x() < lo[b].x(); });
	Groups g(n);
	for (size_t s = 0; s < n; s++)
	{
		const size_t i = byStart[s];
		for (size_t t = s + 1; t < n && lo[byStart[t]].x() <= hi[i].x(); t++)
		{
			const size_t j = byStart[t];
			if (lo[j].y() <= hi[i].y() && lo[i].y() <= hi[j].y() && lo[j].z() <= hi[i].z() && lo[i].z() <= hi[j].z())
				g.join(i, j);
		}
	}
	std::vector<std::vector<size_t>> groups;
	std::vector<size_t> groupOfRoot(n, n);
	for (size_t i = 0; i < n; i++)  // ascending: a root comes first in its group
	{
		const size_t r = g.root(i);
		if (groupOfRoot[r] == n)
		{
			groupOfRoot[r] = groups.size();
			groups.emplace_back();
		}
		groups[groupOfRoot[r]].push_back(i);
	}
	return groups;
}

bool centredOnDecodedTag(const OrientedBox& box, const TagDetection& tag)
{
	return (box.center - tag.position()).norm() < 0.5 * tag.size;
}

}  // namespace tagmap
