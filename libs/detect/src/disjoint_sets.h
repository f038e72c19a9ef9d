// Union-find over indices 0..n-1, with path halving; a set's root is its
// smallest index, so the sets come out in a fixed order whatever the order
// of the unions. Shared by the clustering and the decode schedule.
// Private to tagmap_detect.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace tagmap::detail
{
struct DisjointSets
{
	std::vector<uint32_t> parent;
	explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
	uint32_t find(uint32_t a)
	{
		while (parent[a] != a) a = parent[a] = parent[parent[a]];
		return a;
	}
	void unite(uint32_t a, uint32_t b)
	{
		a = find(a);
		b = find(b);
		if (a != b) parent[std::max(a, b)] = std::min(a, b);
	}
};

}  // namespace tagmap::detail
