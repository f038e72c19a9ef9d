#include "tagmap/localize/window_disagreement.h"

#include <algorithm>
#include <cmath>

namespace tagmap::localize
{
double windowMisregistration(const TagDetection& tag, const mrpt::maps::CPointsMapXYZI& merged,
							 const std::vector<size_t>& scanStarts, double surfaceNoise,
							 const WindowDisagreementParams& params)
{
	const auto& xs = merged.getPointsBufferRef_x();
	const auto& ys = merged.getPointsBufferRef_y();
	const auto& zs = merged.getPointsBufferRef_z();
	const Eigen::Isometry3d toTag = tag.pose.inverse();
	const double half = 0.5 * tag.size, slab = params.slabNoises * surfaceNoise;

	// Per scan: points on the tag, their mean offset along the normal, and
	// the sum of squares about that mean (pooled into the noise estimate).
	struct Scan
	{
		double n = 0, mean = 0, ss = 0;
	};
	std::vector<Scan> scans;
	for (size_t s = 0; s < scanStarts.size(); s++)
	{
		const size_t end = s + 1 < scanStarts.size() ? scanStarts[s + 1] : merged.size();
		std::vector<double> offsets;
		for (size_t i = scanStarts[s]; i < end; i++)
		{
			const Eigen::Vector3d q = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
			if (std::abs(q.x()) <= half && std::abs(q.y()) <= half && std::abs(q.z()) <= slab)
				offsets.push_back(q.z());
		}
		if (offsets.size() < params.minPointsPerScan) continue;
		Scan sc;
		sc.n = static_cast<double>(offsets.size());
		for (double z : offsets) sc.mean += z / sc.n;
		for (double z : offsets) sc.ss += (z - sc.mean) * (z - sc.mean);
		scans.push_back(sc);
	}
	if (scans.size() < 2) return 0;

	double total = 0, mean = 0, withinSS = 0;
	for (const Scan& s : scans) total += s.n;
	for (const Scan& s : scans) mean += s.n * s.mean / total, withinSS += s.ss;
	const double k = static_cast<double>(scans.size());
	const double noiseVar = withinSS / (total - k);  // one point's offset noise
	double betweenSS = 0;  // sum over scans of n (scan mean - overall mean)^2
	for (const Scan& s : scans) betweenSS += s.n * (s.mean - mean) * (s.mean - mean);
	// Noise alone makes betweenSS about (k - 1) noiseVar: one-way analysis of
	// variance. What is left, per point, is the scans' misregistration.
	return std::sqrt(std::max(0.0, (betweenSS - (k - 1) * noiseVar) / total));
}

void addPositionUncertainty(TagDetection& tag, double sigma)
{
	for (int i = 0; i < 3; i++) tag.covariance(i, i) += sigma * sigma;
}

}  // namespace tagmap::localize
