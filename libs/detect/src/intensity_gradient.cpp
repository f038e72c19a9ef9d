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
// Least-squares intensity slope at `centre` from the points within r.
// Coordinates are taken relative to the centre for numerical stability.
// The ridge term keeps the fit well-posed on a plane, where the slope
// along the normal is unobservable; it then comes out near zero.
double gradientNorm(const Eigen::Vector3f& centre, const float* xs, const float* ys, const float* zs, const float* is,
					const VoxelGrid& grid, double radius, int minNeighbours)
{
	const double r2 = radius * radius;
	Eigen::Matrix3d sxx = Eigen::Matrix3d::Zero();
	Eigen::Vector3d sx = Eigen::Vector3d::Zero(), sxi = Eigen::Vector3d::Zero();
	double si = 0;
	int count = 0;
	grid.forEachNeighbourVoxel(grid.keyOf(centre), 1, [&](size_t v) {
		for (const uint32_t* it = grid.begin(v); it != grid.end(v); ++it)
		{
			const Eigen::Vector3d d(xs[*it] - centre.x(), ys[*it] - centre.y(), zs[*it] - centre.z());
			if (d.squaredNorm() > r2) continue;
			const double I = is[*it];
			sxx += d * d.transpose();
			sx += d;
			sxi += d * I;
			si += I;
			count++;
		}
	});
	if (count < minNeighbours) return 0;
	const Eigen::Vector3d mx = sx / count;
	const double mi = si / count;
	Eigen::Matrix3d C = sxx / count - mx * mx.transpose();
	const Eigen::Vector3d c = sxi / count - mx * mi;
	C += Eigen::Matrix3d::Identity() * (1e-3 * C.trace() + 1e-12);
	return C.ldlt().solve(c).norm();
}
}  // namespace

IntensityGradientResult filterByIntensityGradient(const float* xs, const float* ys, const float* zs, const float* is,
												  const VoxelGrid& grid, const IntensityGradientParams& p,
												  unsigned threads)
{
	IntensityGradientResult out;
	size_t n = 0;
	for (size_t v = 0; v < grid.voxelCount(); v++) n += grid.voxelSize(v);
	out.intensitySpread = robustIntensitySpread(is, n);
	if (out.intensitySpread <= 0) return out;
	const double cut = p.threshold * out.intensitySpread / grid.cellSize();

	// Cheap pre-pass: one fit per voxel (at its centroid, over its 3x3x3
	// block). A point whose own fit would pass lies near an edge, and so
	// does its voxel's centroid fit at a lower bar; only those voxels get
	// the per-point fits.
	std::vector<uint8_t> keep(n, 0);
	parallelForBlocks(grid.voxelCount(), threads, [&](size_t vb, size_t ve) {
		for (size_t v = vb; v < ve; v++)
		{
			Eigen::Vector3f c = Eigen::Vector3f::Zero();
			for (const uint32_t* it = grid.begin(v); it != grid.end(v); ++it) c += Eigen::Vector3f(xs[*it], ys[*it], zs[*it]);
			c /= static_cast<float>(grid.voxelSize(v));
			const Eigen::Vector3f mid = grid.voxelCenter(grid.keyOfVoxel(v)).cast<float>();
			// The centroid may sit in a neighbour voxel on a slanted surface; use the voxel centre's key then.
			const Eigen::Vector3f probe = grid.keyOf(c) == grid.keyOfVoxel(v) ? c : mid;
			// 1.5 r: an edge anywhere in the voxel is within reach of the centroid.
			if (gradientNorm(probe, xs, ys, zs, is, grid, 1.5 * grid.cellSize(), p.minNeighbours) < 0.5 * cut) continue;
			for (const uint32_t* it = grid.begin(v); it != grid.end(v); ++it)
			{
				const Eigen::Vector3f q(xs[*it], ys[*it], zs[*it]);
				keep[*it] = gradientNorm(q, xs, ys, zs, is, grid, grid.cellSize(), p.minNeighbours) >= cut;
			}
		}
	}, 256);
	for (size_t i = 0; i < n; i++)
		if (keep[i]) out.keptPoints.push_back(static_cast<uint32_t>(i));
	return out;
}

}  // namespace tagmap
