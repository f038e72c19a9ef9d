#include "tagmap/quantile.h"
#include "tagmap/support_plane.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "tagmap/tag_pose.h"

namespace tagmap
{
namespace
{
/** Points of one region (the tag, or one ring) in the tag frame. The plane
 *  is z = offset + slope . (x, y), with one offset per region: a sheet
 *  proud of its wall, or ink that ranges a few mm differently from paper,
 *  shifts a region without tilting it, and must not stop the growth. */
struct Region
{
	std::vector<Eigen::Vector3d> pts;
	Eigen::Matrix2d S = Eigen::Matrix2d::Zero();  // sum of centred (x, y)(x, y)^T
	Eigen::Vector2d g = Eigen::Vector2d::Zero();  // sum of centred (x, y) z
	double offset = 0;

	/** Keeps the points within `band` of the plane with `slope` and this
	 *  region's own median offset; false when fewer than half are. */
	bool trim(const Eigen::Vector2d& slope, double band)
	{
		if (pts.size() < 20) return false;
		std::vector<double> r;
		for (const auto& p : pts) r.push_back(p.z() - slope.dot(p.head<2>()));
		std::vector<double> sorted = r;
		const double median = medianInPlace(sorted);
		std::vector<Eigen::Vector3d> kept;
		for (size_t k = 0; k < pts.size(); k++)
			if (std::abs(r[k] - median) <= band) kept.push_back(pts[k]);
		if (2 * kept.size() < pts.size() || kept.size() < 20) return false;
		pts.swap(kept);
		Eigen::Vector3d mean = Eigen::Vector3d::Zero();
		for (const auto& p : pts) mean += p;
		mean /= static_cast<double>(pts.size());
		S.setZero();
		g.setZero();
		for (const auto& p : pts)
		{
			const Eigen::Vector3d d = p - mean;
			S += d.head<2>() * d.head<2>().transpose();
			g += d.head<2>() * d.z();
		}
		offset = mean.z() - slope.dot(mean.head<2>());
		return true;
	}
};

/** How much more the slope of a part of the tag scatters than independent
 *  range noise would make it (>= 1): scan lines, angle jitter and beam
 *  footprints correlate neighbouring points' errors. Measured on the four
 *  quadrants of the tag's own points: chi^2 of their slopes against the
 *  pooled one, per degree of freedom. */
double slopeScatterInflation(const Region& tag, const Eigen::Vector2d& pooled, double rms)
{
	Region quadrant[4];
	for (const auto& p : tag.pts) quadrant[(p.x() >= 0) + 2 * (p.y() >= 0)].pts.push_back(p);
	double chi2 = 0;
	int dof = 0;
	for (Region& q : quadrant)
	{
		if (!q.trim(pooled, 1e300)) continue;  // no trimming: just the sums
		const Eigen::Vector2d d = q.S.ldlt().solve(q.g) - pooled;
		chi2 += d.dot(q.S * d) / (rms * rms);
		dof += 2;
	}
	return dof > 2 ? std::max(1.0, std::sqrt(chi2 / (dof - 2))) : 1.0;
}

/** Robust spread of the residuals about a region's plane (1.4826 MAD). */
double robustRms(const Region& r, const Eigen::Vector2d& slope)
{
	std::vector<double> res;
	for (const auto& p : r.pts) res.push_back(p.z() - slope.dot(p.head<2>()));
	const double median = medianInPlace(res);
	for (auto& v : res) v = std::abs(v - median);
	return 1.4826 * medianInPlace(res);
}
}  // namespace

double fitSupportPlane(TagDetection& t, const std::vector<uint32_t>& around, const float* xs, const float* ys,
					   const float* zs, const SupportPlaneParams& p)
{
	if (!p.enabled || !(t.size > 0)) return 0.5;
	// Rings of the region, as half-widths in tag sizes: the tag itself,
	// its quiet zone, then ever wider.
	std::vector<double> edges = {0.5};
	for (double e : {0.625, 0.75, 0.875, 1.0, 1.25, 1.5, 2.0, 2.5})
		if (e <= p.reachSizes + 1e-9) edges.push_back(e);
	std::vector<Region> rings(edges.size());
	const Eigen::Isometry3d inv = t.pose.inverse();
	for (uint32_t i : around)
	{
		const Eigen::Vector3d l = inv * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		const double r = std::max(std::abs(l.x()), std::abs(l.y())) / t.size;
		const auto ring = std::lower_bound(edges.begin(), edges.end(), r);
		if (ring != edges.end()) rings[static_cast<size_t>(ring - edges.begin())].pts.push_back(l);
	}

	// The tag alone: two trimmed rounds from the current (tag-only) plane.
	Region& tag = rings[0];
	Eigen::Vector2d slope = Eigen::Vector2d::Zero();
	if (tag.pts.size() < 20) return 0.5;
	double rms = robustRms(tag, slope);
	if (!(rms > 0)) return 0.5;
	for (int round = 0; round < 2; round++)
	{
		if (!tag.trim(slope, 3 * rms)) return 0.5;
		slope = tag.S.ldlt().solve(tag.g);
	}
	const double inflation = slopeScatterInflation(tag, slope, rms);
	Eigen::Matrix2d S = tag.S;
	Eigen::Vector2d g = tag.g;
	size_t used = tag.pts.size();
	double reached = 0.5;
	for (size_t k = 1; k < rings.size(); k++)
	{
		Region& ring = rings[k];
		if (!ring.trim(slope, 3 * rms)) break;  // a hole, or mostly another surface
		// Its own slope against the one so far, in standard errors.
		const Eigen::Vector2d own = ring.S.ldlt().solve(ring.g);
		const Eigen::Matrix2d cov = inflation * inflation * rms * rms * (ring.S.inverse() + S.inverse());
		const Eigen::Vector2d z = (own - slope).cwiseQuotient(cov.diagonal().cwiseSqrt());
		if (!z.allFinite() || z.cwiseAbs().maxCoeff() > p.stepSigmas) break;
		S += ring.S;
		g += ring.g;
		slope = S.ldlt().solve(g);
		used += ring.pts.size();
		reached = edges[k];
	}

	// Tilt onto the fitted normal; the centre moves along it onto the plane
	// of the tag's own points.
	const Eigen::Vector3d nTag = Eigen::Vector3d(-slope.x(), -slope.y(), 1).normalized();
	const Eigen::Vector3d centre = t.pose * Eigen::Vector3d(0, 0, tag.offset);
	const Eigen::Matrix3d R = t.pose.linear();
	const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), nTag).toRotationMatrix();
	t.pose.linear() = R * turn;
	t.pose.translation() = centre;
	t.corners = cornersFromPose(t.pose, t.size);
	t.pointsUsed = static_cast<int>(used);

	// Slope (dz/dx, dz/dy) standard errors are the tilts about y and x.
	const Eigen::Matrix2d slopeCov = inflation * inflation * rms * rms * S.inverse();
	setTagFrameCovariance(t.covariance, t.pose.linear(), false, {2},
						  Eigen::Matrix<double, 1, 1>(rms * rms / static_cast<double>(tag.pts.size())));
	Eigen::Matrix2d tilts;
	tilts << slopeCov(1, 1), -slopeCov(0, 1), -slopeCov(0, 1), slopeCov(0, 0);
	setTagFrameCovariance(t.covariance, t.pose.linear(), true, {0, 1}, tilts);
	return reached;
}

}  // namespace tagmap
