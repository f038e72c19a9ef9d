#include "tagmap/quantile.h"
#include "tagmap/intensity_gradient.h"

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "tagmap/parallel.h"

namespace tagmap
{
double robustIntensitySpread(const float* is, size_t n)
{
	if (n == 0) return 0;
	const size_t stride = std::max<size_t>(1, n / 200000);
	std::vector<float> s;
	for (size_t i = 0; i < n; i += stride) s.push_back(is[i]);
	const double p5 = quantileInPlace(s, 0.05), p95 = quantileInPlace(s, 0.95);
	return p95 - p5;
}

/** The least-squares slope A = C^-1 c (C: covariance of the neighbours'
 *  positions, c: their covariance with intensity), solved along the
 *  principal directions of C, leaving out those the points hardly spread
 *  along. On a scanned surface the spread along the normal is range noise
 *  only (a few mm against a radius of cm); an intensity slope fitted along
 *  it is noise divided by almost nothing and passed for an edge all over
 *  plain walls of dense terrestrial scans. A direction counts when its
 *  spread is at least half the largest (eigenvalue ratio 1/4): both in-plane
 *  directions of a surface, all three at a corner between surfaces. */
SurfaceSlope surfaceSlope(const Eigen::Matrix3d& C, const Eigen::Vector3d& c)
{
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
	es.computeDirect(C);
	const Eigen::Vector3d lambda = es.eigenvalues();  // ascending
	SurfaceSlope out;
	if (!(lambda(2) > 0)) return out;
	double norm2 = 0;
	for (int k = 0; k < 3; k++)
	{
		if (lambda(k) < 0.25 * lambda(2)) continue;
		const double proj = es.eigenvectors().col(k).dot(c);
		norm2 += proj * proj / (lambda(k) * lambda(k));
		out.explained += proj * proj / lambda(k);
		out.directions++;
	}
	out.norm = std::sqrt(norm2);
	return out;
}

/** An upper bound of surfaceSlope(C, c).norm without solving for C's
 *  eigenvectors: every direction the slope is fitted along has an
 *  eigenvalue of at least a quarter of the largest, and the largest is at
 *  least any Rayleigh quotient (each diagonal entry, and c'Cc / c'c), so
 *  |A| <= |c| / (largest / 4). For a slope along a surface that is 4 |A|:
 *  enough to skip the solve on the plain surfaces most of a map is.
 *  Infinite when C has no positive quotient (the solve then decides). A
 *  small margin covers the solver's rounding: a bound is only used to skip. */
double slopeBound(const Eigen::Matrix3d& C, const Eigen::Vector3d& c)
{
	const double cc = c.squaredNorm();
	const double largest = std::max({C(0, 0), C(1, 1), C(2, 2), cc > 0 ? c.dot(C * c) / cc : 0.0});
	if (!(largest > 0)) return std::numeric_limits<double>::infinity();
	return 1.001 * 4 * std::sqrt(cc) / largest;
}

namespace
{
// The map's points in voxel order, one array per field: a voxel's 3x3x3
// block is a few contiguous runs (one per row), read four points at a time.
// Each array has kPadding elements past the last point, so a run's last
// 1-3 points load as one vector like the others (gradientNorm()).
struct SortedPoints
{
	static constexpr size_t kPadding = 3;
	FilledInParallel<float> x, y, z, i;
};

struct Span
{
	uint32_t begin, end;
};

using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

float sum4(Float4 v) { return (v[0] + v[1]) + (v[2] + v[3]); }

// Lane masks of the first 1, 2 and 3 lanes.
constexpr Int4 kFirstLanes[3] = {{-1, 0, 0, 0}, {-1, -1, 0, 0}, {-1, -1, -1, 0}};

/** The fraction of the intensity variance that a slope fitted along
 *  `directions` directions explains by chance, with probability 1e-3, when
 *  the `count` intensities are pure noise: R^2 then follows
 *  Beta(d/2, (count-d-1)/2), whose upper quantile for d = 2 is
 *  1 - alpha^(2/(count-d-1)) (used for d = 3 too: a slightly lower bar).
 *  Not a bar every point must pass: real edges of sparse scans and of
 *  motion-blurred or noisy spinning maps sit just above R^2 = 0.3 with
 *  10-30 neighbours, below this (tried: 3 of 46 randomized tags lost). It
 *  marks the kept points noise could explain (keptByChance), used only to
 *  split a cluster too large to be a tag. */
double chanceExplained(int count, int directions)
{
	constexpr double kAlpha = 1e-3;
	const int dof = count - std::max(directions, 2) - 1;
	if (dof <= 0) return 1;
	return 1 - std::pow(kAlpha, 2.0 / dof);
}

// Least-squares intensity slope at `centre` from the points within r among
// `spans` (the 3x3x3 voxel block around the centre's voxel). Coordinates
// are taken relative to the centre for numerical stability; the slope is
// solved by surfaceSlope(), along the surface only. The sums are float, four
// points per step in a fixed order, so the result is the same on any
// thread; a point outside r adds exact zeros (no branch per neighbour).
// `enoughBelow`: a caller that only asks whether the result is below this
// gets an upper bound of the norm instead, when the bound already is (no
// eigen-solve; see slopeBound()), and `beatsChance` is then not set.
double gradientNorm(const Eigen::Vector3f& centre, const SortedPoints& pts, const Span* spans, int spanCount,
					double radius, int minNeighbours, double minExplained, bool* beatsChance = nullptr,
					double enoughBelow = 0)
{
	const float cx = centre.x(), cy = centre.y(), cz = centre.z(), r2 = static_cast<float>(radius * radius);
	const Float4 vcx = {cx, cx, cx, cx}, vcy = {cy, cy, cy, cy}, vcz = {cz, cz, cz, cz}, vr2 = {r2, r2, r2, r2};
	const Float4 one = {1, 1, 1, 1};
	Float4 sxx{}, sxy{}, sxz{}, syy{}, syz{}, szz{}, sx{}, sy{}, sz{}, sxi{}, syi{}, szi{}, si{}, sii{}, inside{};
	auto accumulate = [&](Float4 X, Float4 Y, Float4 Z, Float4 I, Float4 valid) {
		const Float4 dx = X - vcx, dy = Y - vcy, dz = Z - vcz;
		const Int4 near = (dx * dx + dy * dy + dz * dz) <= vr2;
		const Float4 w = reinterpret_cast<Float4>(near & reinterpret_cast<Int4>(valid));
		const Float4 wx = w * dx, wy = w * dy, wz = w * dz;
		sxx += wx * dx;
		sxy += wx * dy;
		sxz += wx * dz;
		syy += wy * dy;
		syz += wy * dz;
		szz += wz * dz;
		sx += wx;
		sy += wy;
		sz += wz;
		sxi += wx * I;
		syi += wy * I;
		szi += wz * I;
		si += w * I;
		sii += w * I * I;
		inside += w;
	};
	Float4 X, Y, Z, I;
	const auto load = [&](uint32_t k) {  // points k .. k+3
		std::memcpy(&X, pts.x.data() + k, sizeof X);
		std::memcpy(&Y, pts.y.data() + k, sizeof Y);
		std::memcpy(&Z, pts.z.data() + k, sizeof Z);
		std::memcpy(&I, pts.i.data() + k, sizeof I);
	};
	for (int s = 0; s < spanCount; s++)
	{
		uint32_t k = spans[s].begin;
		for (; k + 4 <= spans[s].end; k += 4)
		{
			load(k);
			accumulate(X, Y, Z, I, one);
		}
		if (k < spans[s].end)  // the last 1-3 points, the rest of the lanes masked off
		{
			// The lanes past the run hold the next points (or the padding):
			// they become the centre with no intensity, which add exact
			// zeros, whatever those points are.
			const Int4 lanes = kFirstLanes[spans[s].end - k - 1];
			load(k);
			accumulate(lanes ? X : vcx, lanes ? Y : vcy, lanes ? Z : vcz, lanes ? I : Float4{},
					   lanes ? one : Float4{});
		}
	}
	const int count = static_cast<int>(sum4(inside));
	if (count < minNeighbours) return -1;  // too sparse here to fit: the caller retries at a larger radius
	Eigen::Matrix3d S;
	S << sum4(sxx), sum4(sxy), sum4(sxz), sum4(sxy), sum4(syy), sum4(syz), sum4(sxz), sum4(syz), sum4(szz);
	const Eigen::Vector3d mx = Eigen::Vector3d(sum4(sx), sum4(sy), sum4(sz)) / count;
	const double mi = sum4(si) / count;
	Eigen::Matrix3d C = S / count - mx * mx.transpose();
	const Eigen::Vector3d c = Eigen::Vector3d(sum4(sxi), sum4(syi), sum4(szi)) / count - mx * mi;
	const double varI = sum4(sii) / count - mi * mi;
	if (enoughBelow > 0)
		if (const double bound = slopeBound(C, c); bound < enoughBelow) return bound;
	const SurfaceSlope slope = surfaceSlope(C, c);
	// How much of the intensity variance the plane I = A^T x + b explains.
	// An edge is explained well (about 0.6-0.75 for a step across the
	// neighbourhood); interleaved points of different intensity (a surface
	// merged from two viewpoints at different ranges, speckle) give a
	// slope from noise that explains little. Scale free, like the slope test.
	if (varI <= 0 || slope.explained < minExplained * varI) return 0;
	if (beatsChance) *beatsChance = slope.explained >= chanceExplained(count, slope.directions) * varI;
	return slope.norm;
}

}  // namespace

IntensityGradientResult filterByIntensityGradient(const float* xs, const float* ys, const float* zs, const float* is,
												  const VoxelGrid& grid, double radius, const IntensityGradientParams& p,
												  unsigned threads, double spread, const CountProgressFn& progress)
{
	if (!(radius > 0 && radius <= grid.cellSize()))
		throw std::invalid_argument("filterByIntensityGradient: the radius must be positive and at most the grid's cell");
	IntensityGradientResult out;
	const size_t n = grid.pointCount();
	threads = resolveThreads(threads);
	out.intensitySpread = spread > 0 ? spread : robustIntensitySpread(is, n);
	if (out.intensitySpread <= 0 || n == 0) return out;
	const double cut = p.threshold * out.intensitySpread / radius;

	// The points in voxel order: a voxel's 3x3x3 block is then nine
	// contiguous runs (one per row), read by a forward sweep, instead of 27
	// random lookups and scattered loads per point.
	SortedPoints sorted;
	for (auto* a : {&sorted.x, &sorted.y, &sorted.z, &sorted.i})
	{
		a->resize(n + SortedPoints::kPadding);
		std::fill(a->begin() + static_cast<std::ptrdiff_t>(n), a->end(), 0.0f);
	}
	const uint32_t* order = grid.begin(0);
	parallelForBlocks(n, threads, [&](size_t b, size_t e) {
		for (size_t k = b; k < e; k++)
		{
			const uint32_t j = order[k];
			sorted.x[k] = xs[j];
			sorted.y[k] = ys[j];
			sorted.z[k] = zs[j];
			sorted.i[k] = is[j];
		}
	}, 1 << 16);

	// Cheap pre-pass: one fit per voxel (at its centroid, over its 3x3x3
	// block). A point whose own fit would pass lies near an edge, and so
	// does its voxel's centroid fit at a lower bar; only those voxels get
	// the per-point fits.
	enum : uint8_t
	{
		kDrop = 0,
		kKeep = 1,
		kSparse = 2,
		kKeepByChance = 3,  // kept, but noise explains as much with this many neighbours
		kStateMask = 3
	};
	// A kept point's strength |A| / cut, in the upper six bits: 1 at the
	// bar, in steps of 1/kStrengthSteps, up to 63 steps.
	constexpr double kStrengthSteps = IntensityGradientResult::kStrengthSteps;
	const auto keptAs = [](uint8_t state, double strength) {
		return static_cast<uint8_t>(state | (static_cast<int>(std::min(63.0, strength * kStrengthSteps)) << 2));
	};
	std::vector<uint8_t> keep(n, kDrop);
	std::atomic<size_t> examined{0};
	parallelForBlocks(grid.voxelCount(), threads, [&](size_t vb, size_t ve) {
		VoxelGrid::NeighbourSweep sweep(grid, vb);
		VoxelGrid::NeighbourSweep::Row rows[9];
		Span spans[9];
		for (size_t v = vb; v < ve; v++)
		{
			// The block's rows in ascending order: a row's voxels hold
			// consecutive points, and so do two rows with no voxel between
			// them; each such run is one span.
			const int rowCount = sweep.rows(v, rows);
			int spanCount = 0;
			for (int r = 0; r < rowCount; r++)
			{
				const auto first = static_cast<uint32_t>(grid.voxelOffset(rows[r].first));
				const auto last = static_cast<uint32_t>(grid.voxelOffset(rows[r].end));
				if (spanCount > 0 && spans[spanCount - 1].end == first) spans[spanCount - 1].end = last;
				else spans[spanCount++] = {first, last};
			}
			const size_t first = grid.voxelOffset(v), last = grid.voxelOffset(v + 1);
			Eigen::Vector3f c = Eigen::Vector3f::Zero();
			for (size_t k = first; k < last; k++) c += Eigen::Vector3f(sorted.x[k], sorted.y[k], sorted.z[k]);
			c /= static_cast<float>(last - first);
			// The centroid may sit in a neighbour voxel on a slanted surface; use the voxel centre then.
			const VoxelKey key = grid.keyOfVoxel(v);
			const Eigen::Vector3f probe = grid.keyOf(c) == key ? c : grid.voxelCenter(key).cast<float>();
			// 1.5 r: an edge anywhere in the voxel is within reach of the centroid.
			const double coarse =
				gradientNorm(probe, sorted, spans, spanCount, 1.5 * radius, p.minNeighbours, 0.0, nullptr, 0.5 * cut);
			if (coarse >= 0 && coarse < 0.5 * cut) continue;
			for (size_t k = first; k < last; k++)
			{
				const Eigen::Vector3f q(sorted.x[k], sorted.y[k], sorted.z[k]);
				bool significant = true;
				const double g =
					gradientNorm(q, sorted, spans, spanCount, radius, p.minNeighbours, p.minExplained, &significant, cut);
				if (g < 0) keep[order[k]] = kSparse;
				else if (g >= cut) keep[order[k]] = keptAs(significant ? kKeep : kKeepByChance, g / cut);
			}
		}
		if (progress) progress(examined += grid.voxelOffset(ve) - grid.voxelOffset(vb), n);
	}, 256);
	sorted = {};
	size_t kept = 0;
	for (size_t i = 0; i < n; i++) kept += (keep[i] & kStateMask) == kKeep || (keep[i] & kStateMask) == kKeepByChance;
	out.keptPoints.reserve(kept);
	out.keptStrength.reserve(kept);
	for (size_t i = 0; i < n; i++)
	{
		const uint8_t state = keep[i] & kStateMask;
		if (state == kKeep || state == kKeepByChance)
		{
			out.keptPoints.push_back(static_cast<uint32_t>(i));
			out.keptStrength.push_back(static_cast<uint8_t>(keep[i] >> 2));
		}
		if (state == kKeepByChance) out.keptByChance.push_back(static_cast<uint32_t>(i));
		if (state == kSparse) out.sparsePoints.push_back(static_cast<uint32_t>(i));
	}
	return out;
}

}  // namespace tagmap
