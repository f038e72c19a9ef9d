#include "tagmap/merge_detections.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "tagmap/tag_family.h"

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

bool sameSquare(const TagDetection& a, const TagDetection& b)
{
	return (a.position() - b.position()).norm() < 0.5 * std::max(a.size, b.size);
}

bool sameCode(const TagDetection& a, const TagDetection& b) { return a.family == b.family && a.id == b.id; }

// The same code read facing both ways on one square, where the code is its
// own mirror image: nothing in the code says which face was printed (the
// front-side check, with the sensors' positions, usually does before
// this). For any other code, the mirror image is no read of the same id:
// two faces are two tags (a board printed on both sides) and merge as one.
bool sidesInDoubt(const TagDetection& a, const TagDetection& b)
{
	return sameCode(a, b) && a.pose.linear().col(2).dot(b.pose.linear().col(2)) < 0 && isOwnMirrorImage(a.family, a.id);
}

/** A code read inside a tag spans at most its inner cells: the border ring
 *  takes 2 of at most 9 cells across (aruco_7x7), 7/9 = 0.78 of the size,
 *  and sizes are measured to a few percent. */
constexpr double kNestedSizeRatio = 0.85;

// `inner`'s centre within `outer`'s square (and its plane, to half a
// size), `inner` clearly smaller: a code read into part of a printed tag.
bool nestedIn(const TagDetection& inner, const TagDetection& outer)
{
	if (!(inner.size < kNestedSizeRatio * outer.size)) return false;
	const Eigen::Vector3d q = outer.pose.inverse() * inner.position();
	return std::abs(q.x()) <= 0.5 * outer.size && std::abs(q.y()) <= 0.5 * outer.size &&
		   std::abs(q.z()) <= 0.5 * outer.size;
}

// Whether fit `a` (correlation over its points) beats fit `b` by `sigmas`
// standard errors of the difference of Fisher's z.
bool clearlyBetterFit(const TagDetection& a, const TagDetection& b, double sigmas)
{
	if (a.patternPoints <= 3 || b.patternPoints <= 3) return a.patternFit > b.patternFit;
	auto z = [](double r) { return std::atanh(std::clamp(r, -0.999999, 0.999999)); };
	const double se = std::sqrt(1.0 / (a.patternPoints - 3) + 1.0 / (b.patternPoints - 3));
	return z(a.patternFit) - z(b.patternFit) > sigmas * se;
}
}  // namespace

std::vector<TagDetection> mergeDetections(std::vector<TagDetection> found, const MergeParams& p)
{
	// Reads nested in a larger tag go first, whatever their fit: the inner
	// cells of a tag36h11 can carry a valid 4x4 code.
	std::vector<TagDetection> whole;
	for (const TagDetection& d : found)
		if (std::none_of(found.begin(), found.end(), [&](const TagDetection& o) { return nestedIn(d, o); }))
			whole.push_back(d);
	std::stable_sort(whole.begin(), whole.end(), better);
	std::vector<TagDetection> kept;
	std::vector<bool> ambiguous;
	for (auto& d : whole)
	{
		bool seen = false;
		for (size_t k = 0; k < kept.size(); k++)
			if (sameSquare(kept[k], d))
			{
				seen = true;
				// `kept[k]` fits at least as well (sorted): another code on its
				// square (or a mirror-symmetric code facing the other way)
				// must lose clearly, else the square is ambiguous.
				if ((!sameCode(kept[k], d) || sidesInDoubt(kept[k], d)) && !clearlyBetterFit(kept[k], d, p.conflictSigmas))
					ambiguous[k] = true;
			}
		if (!seen) kept.push_back(std::move(d)), ambiguous.push_back(false);
	}
	std::vector<TagDetection> out;
	for (size_t k = 0; k < kept.size(); k++)
		if (!ambiguous[k]) out.push_back(std::move(kept[k]));
	std::sort(out.begin(), out.end(), [](const TagDetection& a, const TagDetection& b) {
		return std::make_tuple(a.family, a.id, a.position().x(), a.position().y(), a.position().z()) <
			   std::make_tuple(b.family, b.id, b.position().x(), b.position().y(), b.position().z());
	});
	return out;
}

}  // namespace tagmap
