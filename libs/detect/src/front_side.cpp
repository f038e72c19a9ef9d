#include "tagmap/front_side.h"

#include <algorithm>
#include <cmath>

namespace tagmap
{
FrontSideEvidence measureFrontSide(const TagDetection& t, const std::vector<uint32_t>& around, const float* xs,
								   const float* ys, const float* zs, double surface, const FrontSideParams& p)
{
	FrontSideEvidence e;
	const int n = std::max(1, p.columns);
	const double inner = 0.8 * t.size, depth = p.depthSizes * t.size;
	if (!(inner > 0) || !(depth > surface)) return e;
	std::vector<char> front(static_cast<size_t>(n * n), 0), back(front.size(), 0);
	const Eigen::Isometry3d toTag = t.pose.inverse();
	for (uint32_t i : around)
	{
		const Eigen::Vector3d q = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		const double d = std::abs(q.z());
		if (d <= surface || d > depth) continue;
		const int cx = static_cast<int>(std::floor((q.x() / inner + 0.5) * n));
		const int cy = static_cast<int>(std::floor((q.y() / inner + 0.5) * n));
		if (cx < 0 || cy < 0 || cx >= n || cy >= n) continue;
		(q.z() > 0 ? front : back)[static_cast<size_t>(cy * n + cx)] = 1;
	}
	const double cells = static_cast<double>(front.size());
	e.blockedInFront = static_cast<double>(std::count(front.begin(), front.end(), 1)) / cells;
	e.blockedBehind = static_cast<double>(std::count(back.begin(), back.end(), 1)) / cells;
	return e;
}

bool printedFaceLooksIntoSolid(const FrontSideEvidence& e, const FrontSideParams& p)
{
	return p.enabled && e.blockedInFront >= p.blockedFraction && e.blockedBehind <= p.freeFraction;
}

}  // namespace tagmap
