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

/** Where one scan's points lie on the tag (tag frame): count, sum of x, of y. */
struct ScanFootprint
{
	double n = 0, sx = 0, sy = 0;
};

/** The merged tag's drift variance over the scans' between-scan variance.
 *  The tag is found in the current scan's frame, where that scan's points
 *  lie right; each earlier scan was moved there by odometry whose error
 *  grows with the scan's age, a random walk of variance q per scan. The
 *  merged fit is off by the points-weighted mean of the scans' offsets,
 *  variance q * sum over steps j of (share of points from scans older than
 *  j)^2, while k readings of such offsets spread, on average, with a
 *  between-scan variance of q (k + 1) / 6 (equal shares; 0.83 of it at 3
 *  scans with equal points, 1.55 at 10). `scans`: the current one first,
 *  then the earlier ones oldest first. */
double driftOverSpread(const std::vector<ScanFootprint>& scans, size_t readings)
{
	const size_t k = scans.size();
	double total = 0;
	for (const ScanFootprint& s : scans) total += s.n;
	if (k < 2 || readings < 2 || total <= 0) return 0;
	std::vector<double> byAge(k, 0);
	for (size_t s = 0; s < k; s++) byAge[s == 0 ? 0 : k - s] = scans[s].n / total;
	double older = 0, sum = 0;
	for (size_t age = k - 1; age >= 1; age--)
	{
		older += byAge[age];  // share of points from scans at least `age` steps old
		sum += older * older;
	}
	return sum * 6 / (static_cast<double>(readings) + 1);
}

/** Covariance of the turn (about the tag's x, y, z) of a least-squares fit
 *  of all the scans' points when each scan is moved as a whole: along the
 *  normal by an offset of std `normal` (the plane z = a + bx x + by y tilts:
 *  a turn about x is by, about y is -bx), and in the plane by shifts of std
 *  `x`, `y` (a rigid in-plane fit turns by sum(x dy - y dx) / sum(x^2 + y^2),
 *  x and y from the points' centroid). Scans' offsets independent. */
Eigen::Matrix3d tiltAndTurn(const std::vector<ScanFootprint>& scans, const Eigen::Matrix3d& normalEquations,
							double normal, double x, double y)
{
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	const Eigen::Matrix3d& M = normalEquations;  // sum of [1 x y]' [1 x y] over every point
	if (M(0, 0) < 3 || std::abs(M.determinant()) < 1e-18) return cov;
	const Eigen::Matrix3d Minv = M.inverse();
	const double cx = M(0, 1) / M(0, 0), cy = M(0, 2) / M(0, 0);
	const double spread = M(1, 1) - M(0, 0) * cx * cx + M(2, 2) - M(0, 0) * cy * cy;  // sum of x'^2 + y'^2
	Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
	double turn = 0;
	for (const ScanFootprint& s : scans)
	{
		const Eigen::Vector3d a(s.n, s.sx, s.sy);
		scatter += a * a.transpose();
		const double ox = s.sx - s.n * cx, oy = s.sy - s.n * cy;  // the scan's points' sum from the centroid
		turn += y * y * ox * ox + x * x * oy * oy;
	}
	const Eigen::Matrix3d plane = normal * normal * Minv * scatter * Minv;  // covariance of [a bx by]
	cov(0, 0) = plane(2, 2);
	cov(1, 1) = plane(1, 1);
	cov(0, 1) = cov(1, 0) = -plane(1, 2);
	if (spread > 0) cov(2, 2) = turn / (spread * spread);
	return cov;
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
	std::vector<ScanFootprint> footprints;
	Eigen::Matrix3d normalEquations = Eigen::Matrix3d::Zero();
	for (size_t s = 0; s < scanStarts.size(); s++)
	{
		const size_t end = s + 1 < scanStarts.size() ? scanStarts[s + 1] : merged.size();
		PlaneImage onTag;
		std::vector<double> offsets;
		ScanFootprint footprint;
		for (size_t i = scanStarts[s]; i < end; i++)
		{
			const Eigen::Vector3d q = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
			if (std::abs(q.x()) > half || std::abs(q.y()) > half || std::abs(q.z()) > slab) continue;
			onTag.inliers.push_back(static_cast<uint32_t>(i));
			offsets.push_back(q.z());
			const Eigen::Vector3d row(1, q.x(), q.y());
			normalEquations += row * row.transpose();
			footprint.n += 1, footprint.sx += q.x(), footprint.sy += q.y();
		}
		// Every scan's points are in the merged fit, voting or not.
		footprints.push_back(footprint);
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
	// The scans' offsets turn the merged fit as they spread (independent of
	// each other: the fit's turn depends on their differences).
	m.rotation = tiltAndTurn(footprints, normalEquations, m.alongNormal, m.inPlaneX, m.inPlaneY);
	// The merged tag itself is off by their drift from the current scan.
	m.alongNormal *= std::sqrt(driftOverSpread(footprints, normal.size()));
	const double inPlane = std::sqrt(driftOverSpread(footprints, x.size()));
	m.inPlaneX *= inPlane, m.inPlaneY *= inPlane;
	return m;
}

void addMisregistration(TagDetection& tag, const WindowMisregistration& m)
{
	const Eigen::Matrix3d R = tag.pose.linear();
	const Eigen::Vector3d position(m.inPlaneX * m.inPlaneX, m.inPlaneY * m.inPlaneY, m.alongNormal * m.alongNormal);
	tag.covariance.topLeftCorner<3, 3>() += R * position.asDiagonal() * R.transpose();
	tag.covariance.bottomRightCorner<3, 3>() += R * m.rotation * R.transpose();
}

}  // namespace tagmap::localize
