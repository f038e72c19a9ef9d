#include "tagmap/quantile.h"
#include "tagmap/surface_noise.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

namespace tagmap
{
namespace
{
// The points within `radius` of point i, into `scratch`.
void neighboursWithin(const float* xs, const float* ys, const float* zs, const VoxelGrid& grid, uint32_t i,
					  double radius, std::vector<uint32_t>& scratch)
{
	const Eigen::Vector3f p(xs[i], ys[i], zs[i]);
	const int reach = static_cast<int>(std::ceil(radius / grid.cellSize()));
	const float r2 = static_cast<float>(radius * radius);
	scratch.clear();
	grid.forEachNeighbourVoxel(grid.keyOf(p), reach, [&](size_t v) {
		for (const uint32_t* q = grid.begin(v); q != grid.end(v); ++q)
			if ((Eigen::Vector3f(xs[*q], ys[*q], zs[*q]) - p).squaredNorm() <= r2) scratch.push_back(*q);
	});
}

// Plane-fit RMS of the points within `radius` of point i, or -1 when too
// few. At most ~256 neighbours are used (a strided subset): enough for a
// standard deviation, and bounded cost in dense scans.
double neighbourhoodRms(const float* xs, const float* ys, const float* zs, const VoxelGrid& grid, uint32_t i,
						double radius, size_t minNeighbours, std::vector<uint32_t>& scratch)
{
	const Eigen::Vector3f p(xs[i], ys[i], zs[i]);
	neighboursWithin(xs, ys, zs, grid, i, radius, scratch);
	if (scratch.size() < minNeighbours) return -1;
	const size_t stride = std::max<size_t>(1, scratch.size() / 256);
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
	size_t count = 0;
	for (size_t k = 0; k < scratch.size(); k += stride, count++)
	{
		// Relative to the sample point: float-precision safe far from the origin.
		const Eigen::Vector3d d = (Eigen::Vector3f(xs[scratch[k]], ys[scratch[k]], zs[scratch[k]]) - p).cast<double>();
		sum += d;
		outer += d * d.transpose();
	}
	const Eigen::Vector3d mean = sum / static_cast<double>(count);
	const Eigen::Matrix3d cov = outer / static_cast<double>(count) - mean * mean.transpose();
	const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov, Eigen::EigenvaluesOnly).eigenvalues()(0);
	return std::sqrt(std::max(0.0, smallest));
}
}  // namespace

double estimateSurfaceNoise(const float* xs, const float* ys, const float* zs, size_t n, const VoxelGrid& grid,
							const SurfaceNoiseParams& p)
{
	if (n == 0 || p.samples == 0) return 0;
	std::vector<uint32_t> scratch;
	std::vector<double> rms;
	double radius = grid.cellSize();
	// No more samples than the points hold neighbourhoods apart: beyond n
	// over a neighbourhood's points they share most of their points and
	// add little to the median. A scan's points near its reads (10 k, ~14
	// a neighbourhood) hold ~650; maps hold far more than p.samples, and
	// sample as before. A pilot of 64 evenly strided points measures the
	// neighbourhood's size.
	size_t cap = p.samples;
	{
		const size_t pilot = 64, stride = std::max<size_t>(1, n / pilot);
		size_t found = 0, count = 0;
		for (size_t i = stride / 2; i < n; i += stride, count++)
		{
			neighboursWithin(xs, ys, zs, grid, static_cast<uint32_t>(i), radius, scratch);
			found += scratch.size();
		}
		if (found > 0) cap = std::max(std::min<size_t>(p.samples, 200), std::min(p.samples, n * count / found));
	}
	for (int doubling = 0; doubling <= p.maxDoublings; doubling++, radius *= 2)
	{
		rms.clear();
		const size_t samples = std::max<size_t>(cap >> doubling, std::min<size_t>(cap, 200));
		const size_t stride = std::max<size_t>(1, n / samples);
		for (size_t i = stride / 2; i < n; i += stride)
		{
			const double s = neighbourhoodRms(xs, ys, zs, grid, static_cast<uint32_t>(i), radius, p.minNeighbours, scratch);
			if (s >= 0) rms.push_back(s);
		}
		if (rms.empty()) return 0;
		const double median = medianInPlace(rms);
		if (median * p.minRadiusOverNoise <= radius) return median;
	}
	return rms[rms.size() / 2];  // the widest ball's estimate: a lower bound
}

}  // namespace tagmap
