#include "tagmap/localize/window_disagreement.h"

#include <algorithm>
#include <cmath>

#include "tagmap/intermediate_plane.h"
#include "tagmap/pattern_refinement.h"
#include "tagmap/tag_family.h"

namespace tagmap::localize
{
namespace
{
/** One scan's reading of one quantity: its value and its own variance. */
struct Reading
{
	double value = 0, variance = 0;
};

/** Standard deviation of the readings beyond their own uncertainty: the
 *  between-scan variance of a random-effects model, by DerSimonian and
 *  Laird's moment estimator (each reading weighed by its inverse variance,
 *  so a scan whose points barely constrain a quantity, a petal trace across
 *  the tag along its own direction, neither counts nor hides the others).
 *  0 when the readings agree as well as their variances say they would. */
double spreadBeyondNoise(const std::vector<Reading>& r)
{
	constexpr double kTiny = 1e-18;  // a reading claiming no variance at all
	double sw = 0, sww = 0, mean = 0;
	for (const Reading& x : r)
	{
		const double w = 1 / std::max(x.variance, kTiny);
		sw += w, sww += w * w, mean += w * x.value;
	}
	mean /= sw;
	double q = 0;
	for (const Reading& x : r) q += (x.value - mean) * (x.value - mean) / std::max(x.variance, kTiny);
	const double k = static_cast<double>(r.size());
	return std::sqrt(std::max(0.0, (q - (k - 1)) / (sw - sww / sw)));
}
}  // namespace

WindowMisregistration windowMisregistration(const TagDetection& tag, const mrpt::maps::CPointsMapXYZI& merged,
											const std::vector<size_t>& scanStarts, double surfaceNoise,
											const WindowDisagreementParams& params)
{
	WindowMisregistration m;
	const float* xs = merged.getPointsBufferRef_x().data();
	const float* ys = merged.getPointsBufferRef_y().data();
	const float* zs = merged.getPointsBufferRef_z().data();
	const float* is = merged.getPointsBufferRef_intensity().data();
	const Eigen::Isometry3d toTag = tag.pose.inverse();
	const TagBitmap bm = renderTagBitmap(tag.family, tag.id);
	// The whole grid (quiet zone included): the pattern fit reads all of it.
	const double half = 0.5 * tag.size * bm.cells / bm.borderCells, slab = params.slabNoises * surfaceNoise;
	// A scan's shift counts when its points fit the bitmap as well as the
	// detector asks of a tag (refinement.min_pattern_fit's default): a few
	// petal traces across the tag fit worse, and their fits wander.
	PatternRefinementParams fit;
	fit.estimateSize = false;

	std::vector<Reading> normal, x, y;
	for (size_t s = 0; s < scanStarts.size(); s++)
	{
		const size_t end = s + 1 < scanStarts.size() ? scanStarts[s + 1] : merged.size();
		PlaneImage onTag;
		std::vector<double> offsets;
		for (size_t i = scanStarts[s]; i < end; i++)
		{
			const Eigen::Vector3d q = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
			if (std::abs(q.x()) > half || std::abs(q.y()) > half || std::abs(q.z()) > slab) continue;
			onTag.inliers.push_back(static_cast<uint32_t>(i));
			offsets.push_back(q.z());
		}
		if (offsets.size() < params.minPointsPerScan) continue;
		const double n = static_cast<double>(offsets.size());
		double mean = 0, ss = 0;
		for (double z : offsets) mean += z / n;
		for (double z : offsets) ss += (z - mean) * (z - mean);
		normal.push_back({mean, ss / (n - 1) / n});

		onTag.localSpacing = 2 * half / std::sqrt(n);
		TagDetection fitted = tag;
		if (!refineWithPattern(fitted, onTag, xs, ys, zs, is, fit)) continue;
		const Eigen::Isometry3d d = toTag * fitted.pose;  // the scan's tag in the merged tag's frame
		const Eigen::Matrix3d R = tag.pose.linear();
		const Eigen::Matrix3d cp = R.transpose() * fitted.covariance.topLeftCorner<3, 3>() * R;
		x.push_back({d.translation().x(), cp(0, 0)});
		y.push_back({d.translation().y(), cp(1, 1)});
	}
	m.scansCompared = static_cast<int>(normal.size());
	if (normal.size() >= 2) m.alongNormal = spreadBeyondNoise(normal);
	if (x.size() >= 2)
	{
		m.inPlaneX = spreadBeyondNoise(x);
		m.inPlaneY = spreadBeyondNoise(y);
	}
	return m;
}

void addMisregistration(TagDetection& tag, const WindowMisregistration& m)
{
	const Eigen::Matrix3d R = tag.pose.linear();
	const Eigen::Vector3d position(m.inPlaneX * m.inPlaneX, m.inPlaneY * m.inPlaneY, m.alongNormal * m.alongNormal);
	tag.covariance.topLeftCorner<3, 3>() += R * position.asDiagonal() * R.transpose();
}

}  // namespace tagmap::localize
