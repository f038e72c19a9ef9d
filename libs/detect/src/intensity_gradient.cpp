#include "tagmap/intensity_gradient.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "tagmap/parallel.h"

namespace tagmap
{
double robustIntensitySpread(const float* is, size_t n)
{
	if (n == 0) return 0;
	const size_t stride = std::max<size_t>(1, n / 200000);
	std::vector<float> s;
	for (size_t i = 0; i < n; i += stride) s.push_back(is[i]);
	auto pct = [&](double q) {
		auto it = s.begin() + static_cast<long>(q * (s.size() - 1));
		std::nth_element(s.begin(), it, s.end());
		return static_cast<double>(*it);
	};
	const double p5 = pct(0.05), p95 = pct(0.95);
	return p95 - p5;
}

namespace
{
struct Point4
{
	float x, y, z, i;
};

// Least-squares intensity slope at `centre` from the points within r of
// `pts` (the 3x3x3 voxel block around the centre's voxel, in ascending
// voxel order: the same points, in the same order, as a neighbour query).
// Coordinates are taken relative to the centre for numerical stability.
// The ridge term keeps the fit well-posed on a plane, where the slope
// along the normal is unobservable; it then comes out near zero.
double gradientNorm(const Eigen::Vector3f& centre, const std::vector<Point4>& pts, double radius, int minNeighbours)
{
	const double r2 = radius * radius;
	double sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
	double sx = 0, sy = 0, sz = 0, sxi = 0, syi = 0, szi = 0, si = 0;
	int count = 0;
	for (const Point4& q : pts)
	{
		const double dx = q.x - centre.x(), dy = q.y - centre.y(), dz = q.z - centre.z();
		if (dx * dx + dy * dy + dz * dz > r2) continue;
		const double I = q.i;
		sxx += dx * dx;
		sxy += dx * dy;
		sxz += dx * dz;
		syy += dy * dy;
		syz += dy * dz;
		szz += dz * dz;
		sx += dx;
		sy += dy;
		sz += dz;
		sxi += dx * I;
		syi += dy * I;
		szi += dz * I;
		si += I;
		count++;
	}
	if (count < minNeighbours) return 0;
	Eigen::Matrix3d S;
	S << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
	const Eigen::Vector3d mx = Eigen::Vector3d(sx, sy, sz) / count;
	const double mi = si / count;
	Eigen::Matrix3d C = S / count - mx * mx.transpose();
	const Eigen::Vector3d c = Eigen::Vector3d(sxi, syi, szi) / count - mx * mi;
	C += Eigen::Matrix3d::Identity() * (1e-3 * C.trace() + 1e-12);
	return C.ldlt().solve(c).norm();
}
}  // namespace

IntensityGradientResult filterByIntensityGradient(const float* xs, const float* ys, const float* zs, const float* is,
												  const VoxelGrid& grid, const IntensityGradientParams& p,
												  unsigned threads)
{
	IntensityGradientResult out;
	const size_t n = grid.pointCount();
	threads = resolveThreads(threads);
	out.intensitySpread = robustIntensitySpread(is, n);
	if (out.intensitySpread <= 0 || n == 0) return out;
	const double cut = p.threshold * out.intensitySpread / grid.cellSize();

	// The points in voxel order, x y z I side by side: a voxel's 3x3x3 block
	// is then nine contiguous runs (one per row), read by a forward sweep,
	// instead of 27 random lookups and scattered loads per point.
	std::vector<Point4> sorted(n);
	const uint32_t* order = grid.begin(0);
	parallelForBlocks(n, threads, [&](size_t b, size_t e) {
		for (size_t k = b; k < e; k++)
		{
			const uint32_t j = order[k];
			sorted[k] = {xs[j], ys[j], zs[j], is[j]};
		}
	}, 1 << 16);

	// Cheap pre-pass: one fit per voxel (at its centroid, over its 3x3x3
	// block). A point whose own fit would pass lies near an edge, and so
	// does its voxel's centroid fit at a lower bar; only those voxels get
	// the per-point fits.
	std::vector<uint8_t> keep(n, 0);
	parallelForBlocks(grid.voxelCount(), threads, [&](size_t vb, size_t ve) {
		VoxelGrid::NeighbourSweep sweep(grid, vb);
		uint32_t block[27];
		std::vector<Point4> near;
		near.reserve(256);
		for (size_t v = vb; v < ve; v++)
		{
			const int count = sweep.neighbours(v, block);
			near.clear();
			for (int b = 0; b < count; b++)
				near.insert(near.end(), sorted.begin() + grid.voxelOffset(block[b]),
							sorted.begin() + grid.voxelOffset(block[b] + 1));
			const size_t first = grid.voxelOffset(v), last = grid.voxelOffset(v + 1);
			Eigen::Vector3f c = Eigen::Vector3f::Zero();
			for (size_t k = first; k < last; k++) c += Eigen::Vector3f(sorted[k].x, sorted[k].y, sorted[k].z);
			c /= static_cast<float>(last - first);
			const Eigen::Vector3f mid = grid.voxelCenter(grid.keyOfVoxel(v)).cast<float>();
			// The centroid may sit in a neighbour voxel on a slanted surface; use the voxel centre's key then.
			const Eigen::Vector3f probe = grid.keyOf(c) == grid.keyOfVoxel(v) ? c : mid;
			// 1.5 r: an edge anywhere in the voxel is within reach of the centroid.
			if (gradientNorm(probe, near, 1.5 * grid.cellSize(), p.minNeighbours) < 0.5 * cut) continue;
			for (size_t k = first; k < last; k++)
			{
				const Eigen::Vector3f q(sorted[k].x, sorted[k].y, sorted[k].z);
				keep[order[k]] = gradientNorm(q, near, grid.cellSize(), p.minNeighbours) >= cut;
			}
		}
	}, 256);
	sorted = {};
	size_t kept = 0;
	for (size_t i = 0; i < n; i++) kept += keep[i];
	out.keptPoints.reserve(kept);
	for (size_t i = 0; i < n; i++)
		if (keep[i]) out.keptPoints.push_back(static_cast<uint32_t>(i));
	return out;
}

}  // namespace tagmap
