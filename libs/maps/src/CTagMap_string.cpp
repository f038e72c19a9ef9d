// CTagMap::asString(): the table RawLogViewer and friends print for a map.
// Angles in degrees, since this text is for people (docs/RESULT_FORMAT.md).
#include <mrpt/core/format.h>

#include <cmath>

#include "tagmap/maps/CTagMap.h"

namespace tagmap::maps
{
std::string CTagMap::asString() const
{
	const auto& ts = tags();
	std::string s = mrpt::format("CTagMap: %zu tags, %zu points\n", ts.size(), m_points.size());
	s += mrpt::format("%-18s %6s %8s %10s %10s %10s %9s %9s %9s\n", "family", "id", "size[m]", "x[m]", "y[m]", "z[m]",
					  "roll[deg]", "pitch[deg]", "yaw[deg]");
	constexpr double deg = 180.0 / M_PI;
	for (const auto& t : ts)
	{
		const Eigen::Vector3d p = t.position();
		const Eigen::Vector3d rpy = rollPitchYaw(t.pose.linear()) * deg;
		s += mrpt::format("%-18s %6d %8.4f %10.4f %10.4f %10.4f %9.2f %9.2f %9.2f\n", t.family.c_str(), t.id, t.size,
						  p.x(), p.y(), p.z(), rpy.x(), rpy.y(), rpy.z());
	}
	return s;
}

}  // namespace tagmap::maps
