#include "tagmap/quantile.h"
#include "tagmap/candidate_filter.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tagmap
{
bool tooLargeForATag(const OrientedBox& box, double band, const CandidateFilterParams& p)
{
	const double aMax = p.tagSize > 0 ? p.tagSize : p.maxTagSize;
	return std::hypot(box.extent.x(), box.extent.y()) > p.maxOversize * 2 * (aMax + 2 * band);
}

std::optional<Verdict> rejectCandidate(const OrientedBox& box, double band, double noise, const CandidateFilterParams& p)
{
	const double l = box.extent.x(), w = box.extent.y();
	const double h = box.thickness > 0 ? box.thickness : box.extent.z();
	const double aMin = p.tagSize > 0 ? p.tagSize : p.minTagSize;
	// Paper's criterion 1 in the tag plane: a*sqrt(2) <= diag <= 2a; the
	// kept edge band widens the box by up to `band` on every side.
	const double diag = std::hypot(l, w);
	if (diag < std::sqrt(2.0) * aMin * (1 - p.shortfall) || tooLargeForATag(box, band, p)) return Verdict::Size;
	if (w <= 0 || l / w > p.maxAspect) return Verdict::Squareness;
	if (h > p.maxFlatness * w + 2 * noise) return Verdict::NotFlat;
	return std::nullopt;
}

namespace
{
// The corners of a box's face: its length and width about its centre.
std::array<Eigen::Vector3d, 4> faceCorners(const OrientedBox& b)
{
	const Eigen::Vector3d l = 0.5 * b.extent.x() * b.axes.col(0), w = 0.5 * b.extent.y() * b.axes.col(1);
	return {b.center + l + w, b.center + l - w, b.center - l - w, b.center - l + w};
}
}  // namespace

bool sameBox(const OrientedBox& a, const OrientedBox& b, double tolerance)
{
	if ((a.center - b.center).norm() > tolerance || std::abs(a.extent.z() - b.extent.z()) > tolerance) return false;
	const std::array<Eigen::Vector3d, 4> ca = faceCorners(a), cb = faceCorners(b);
	return std::all_of(ca.begin(), ca.end(), [&](const Eigen::Vector3d& p) {
		return std::any_of(cb.begin(), cb.end(), [&](const Eigen::Vector3d& q) { return (p - q).norm() <= tolerance; });
	});
}

std::vector<OrientedBox> squareWindows(const OrientedBox& box, double band, double noise, const CandidateFilterParams& p,
									 const std::vector<double>& along)
{
	std::vector<OrientedBox> out;
	const double l = box.extent.x(), w = box.extent.y();
	if (!(w > 0)) return out;
	const bool longLine = l > p.splitAspect * w;
	if (longLine && along.empty()) return out;
	OrientedBox window = box;
	window.extent.x() = w;
	if (rejectCandidate(window, band, noise, p)) return out;
	// Half-overlapping windows from one end to the other, the last one
	// flush with the far end.
	const int steps = static_cast<int>(std::ceil((l - w) / (0.5 * w)));
	std::vector<double> offsets;
	for (int k = 0; k <= steps; k++) offsets.push_back(std::min(-0.5 * (l - w) + k * 0.5 * w, 0.5 * (l - w)));
	if (longLine)
	{
		// Along a long line (a pillar's corners from floor to roof) only the
		// windows much denser than the line itself can hold a tag: a tag's
		// edges fill its square, a line's only cross it.
		std::vector<size_t> count(offsets.size(), 0);
		for (double a : along)
			for (size_t k = 0; k < offsets.size(); k++) count[k] += std::abs(a - offsets[k]) <= 0.5 * w;
		std::vector<size_t> sorted = count;
		const size_t median = medianInPlace(sorted);
		std::vector<double> dense;
		for (size_t k = 0; k < offsets.size(); k++)
		{
			const bool peak = (k == 0 || count[k] >= count[k - 1]) && (k + 1 == count.size() || count[k] >= count[k + 1]);
			if (peak && count[k] >= 3 * std::max<size_t>(median, 1)) dense.push_back(offsets[k]);
		}
		offsets = dense;
	}
	for (double offset : offsets)
	{
		window.center = box.center + box.axes.col(0) * offset;
		out.push_back(window);
	}
	return out;
}

}  // namespace tagmap
