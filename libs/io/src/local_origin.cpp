// The local origin a map is stored around (point_cloud_io.h): georeferenced
// maps sit millions of metres from their frame's origin, where float32 steps
// are 0.25-0.5 m; relative to their own median they keep sub-millimetre steps.
#include <algorithm>
#include <cmath>

#include "tagmap/quantile.h"
#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
std::vector<Eigen::Vector3d> LoadReport::localViewpoints() const
{
	std::vector<Eigen::Vector3d> local = viewpoints;
	for (Eigen::Vector3d& v : local) v -= origin;
	return local;
}

Eigen::Vector3d chooseLocalOrigin(std::vector<Eigen::Vector3d> points)
{
	Eigen::Vector3d origin = Eigen::Vector3d::Zero();
	// Sentinels (1e30, FLT_MAX) and NaN must not become the origin: every
	// place on Earth is within kMaxAbsCoordinate of a projected or ECEF frame's origin.
	points.erase(std::remove_if(points.begin(), points.end(),
								[](const Eigen::Vector3d& p) { return !(p.cwiseAbs().maxCoeff() <= kMaxAbsCoordinate); }),
				 points.end());
	if (points.empty()) return origin;
	std::vector<double> axis(points.size());
	for (int a = 0; a < 3; ++a)
	{
		for (size_t k = 0; k < points.size(); ++k) axis[k] = points[k][a];
		const double median = medianInPlace(axis);
		// Whole metres: the origin prints exactly, and subtracting it keeps
		// the digits below the metre as the file had them.
		if (std::fabs(median) > kLocalOriginBeyond) origin[a] = std::round(median);
	}
	return origin;
}

}  // namespace tagmap::io
