#include "tagmap/localize/trajectory_tum.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"

namespace tagmap::localize
{
Trajectory readTum(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError(path, "", "cannot open");
	Trajectory out;
	std::string line;
	for (size_t n = 1; std::getline(in, line); n++)
	{
		const auto first = line.find_first_not_of(" \t\r");
		if (first == std::string::npos || line[first] == '#') continue;
		std::istringstream s(line);
		StampedPose p;
		double x, y, z, qx, qy, qz, qw;
		std::string extra;
		if (!(s >> p.stamp >> x >> y >> z >> qx >> qy >> qz >> qw) || (s >> extra))
			throw InputError(path, "line " + std::to_string(n), "expected 't x y z qx qy qz qw'");
		const Eigen::Quaterniond q(qw, qx, qy, qz);
		if (!(q.norm() > 0.5 && q.norm() < 1.5))
			throw InputError(path, "line " + std::to_string(n), "quaternion is not a rotation");
		p.pose.linear() = q.normalized().toRotationMatrix();
		p.pose.translation() = Eigen::Vector3d(x, y, z);
		out.push_back(p);
	}
	return out;
}

std::vector<Eigen::Vector3d> readTumPositions(const std::string& path)
{
	std::vector<Eigen::Vector3d> positions;
	for (const StampedPose& p : readTum(path)) positions.push_back(p.pose.translation());
	if (positions.empty()) throw InputError(path, "", "no pose in the trajectory (TUM lines: t x y z qx qy qz qw)");
	return positions;
}

std::string toTum(const Trajectory& trajectory)
{
	std::string s;
	char line[256];
	for (const StampedPose& p : trajectory)
	{
		const Eigen::Quaterniond q(p.pose.linear());
		const Eigen::Vector3d t = p.pose.translation();
		std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.stamp, t.x(), t.y(), t.z(), q.x(),
					  q.y(), q.z(), q.w());
		s += line;
	}
	return s;
}

void writeTum(const std::string& path, const Trajectory& trajectory)
{
	const std::string text = toTum(trajectory);
	writeFileAtomically(path, [&](std::ostream& o) { o << text; });
}

}  // namespace tagmap::localize
