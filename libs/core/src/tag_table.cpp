#include "tagmap/tag_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tagmap
{
namespace
{
template <class... A>
std::string fmt(const char* f, A... a)
{
	char buf[256];
	std::snprintf(buf, sizeof buf, f, a...);
	return buf;
}
}  // namespace

std::string tagTable(const std::vector<TagDetection>& tags, const TagTableColumns& c)
{
	constexpr double deg = 180.0 / M_PI;
	const bool first = static_cast<bool>(c.first);
	std::string s;
	if (first) s += fmt("%-10s ", c.firstHeader.c_str());
	s += fmt("%-18s %6s %8s", "family", "id", "size[m]");
	if (c.range) s += fmt(" %8s", "range[m]");
	s += fmt(" %10s %10s %10s %9s %10s %9s", "x[m]", "y[m]", "z[m]", "roll[deg]", "pitch[deg]", "yaw[deg]");
	if (c.points) s += fmt(" %7s", "points");
	if (c.stdDev) s += fmt(" | %-17s | %s", "std xyz [cm]", "std rpy [deg]");
	s += "\n";
	for (const TagDetection& t : tags)
	{
		const Eigen::Vector3d p = t.position();
		const Eigen::Vector3d rpy = rollPitchYaw(t.pose.linear()) * deg;
		if (first) s += fmt("%-10s ", c.first(t).c_str());
		s += fmt("%-18s %6d %8.4f", t.family.c_str(), t.id, t.size);
		if (c.range) s += fmt(" %8.3f", p.norm());
		s += fmt(" %10.4f %10.4f %10.4f %9.2f %10.2f %9.2f", p.x(), p.y(), p.z(), rpy.x(), rpy.y(), rpy.z());
		if (c.points) s += fmt(" %7d", t.pointsUsed);
		if (c.stdDev)
		{
			const auto sd = [&](int i) { return std::sqrt(std::max(0.0, t.covariance(i, i))); };
			s += fmt(" | %5.1f %5.1f %5.1f | %5.2f %5.2f %5.2f", 100 * sd(0), 100 * sd(1), 100 * sd(2), sd(3) * deg,
					 sd(4) * deg, sd(5) * deg);
		}
		s += "\n";
	}
	return s;
}

}  // namespace tagmap
