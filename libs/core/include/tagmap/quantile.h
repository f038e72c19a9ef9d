// Order statistics of a sample: medians and percentiles are how tagmap
// measures a map (spacing, noise, intensity spread) without being moved by
// the few outliers every LiDAR map has. One definition, so every stage picks
// the same element for the same fraction.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tagmap
{
/** The element at `fraction` of the sorted order (0 the smallest, 1 the
 *  largest; index floor(fraction * (n - 1))). `values` is partially
 *  reordered (nth_element: O(n)), so several quantiles of one sample can be
 *  taken in any order. `values` must not be empty. */
template <class T>
T quantileInPlace(std::vector<T>& values, double fraction)
{
	const double clamped = std::clamp(fraction, 0.0, 1.0);
	const auto k = static_cast<std::ptrdiff_t>(clamped * static_cast<double>(values.size() - 1));
	std::nth_element(values.begin(), values.begin() + k, values.end());
	return values[static_cast<size_t>(k)];
}

/** The upper median (element n / 2 of the sorted order); `values` is
 *  partially reordered and must not be empty. */
template <class T>
T medianInPlace(std::vector<T>& values)
{
	const auto k = static_cast<std::ptrdiff_t>(values.size() / 2);
	std::nth_element(values.begin(), values.begin() + k, values.end());
	return values[values.size() / 2];
}

}  // namespace tagmap
