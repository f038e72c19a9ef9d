// The local origin a map is stored around (point_cloud_io.h): georeferenced
// maps sit millions of metres from their frame's origin, where float32 steps
// are 0.25-0.5 m; relative to their own median they keep sub-millimetre steps.
#include <algorithm>
#include <cmath>

#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
Eigen::Vector3d chooseLocalOrigin(std::vector<Eigen::Vector3d> points)
{
	Eigen::Vector3d origin = Eigen::Vector3d::Zero();
	// Sentinels (1e30, FLT_MAX) and NaN must not become the origin: every
	// place on Earth is within kMaxAbsCoordinate of a projected or ECEF frame's origin.
	points.erase(std::remove_if(points.begin(), points.end(),
								[](const Eigen::Vector3d& p) { return !(p.cwiseAbs().maxCoeff() <= kMaxAbsCoordinate); }),
				 points.end());
	if (points.empty()) return origin;
	const auto mid = points.begin() + static_cast<std::ptrdiff_t>(points.size() / 2);
	for (int a = 0; a < 3; ++a)
	{
		std::nth_element(points.begin(), mid, points.end(),
						 [a](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return p[a] < q[a]; });
		const double median = (*mid)[a];
		// Whole metres: the origin prints exactly, and subtracting it keeps
		// the digits below the metre as the file had them.
		if (std::fabs(median) > kLocalOriginBeyond) origin[a] = std::round(median);
	}
	return origin;
}

}  // namespace tagmap::io
