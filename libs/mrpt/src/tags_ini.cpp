#include "tagmap/mrpt/tags_ini.h"

#include <mrpt/core/format.h>

#include <sstream>

#include "tagmap/errors.h"

namespace tagmap::mrpt_bridge
{
namespace
{
std::string key(unsigned i, const char* what) { return mrpt::format("tag_%03u_%s", i, what); }

// %.17g: the ini must reproduce the tags bit-for-bit (CTagMap round trips).
std::string numbers(const double* v, size_t n)
{
	std::string s;
	for (size_t k = 0; k < n; k++) s += mrpt::format(k ? " %.17g" : "%.17g", v[k]);
	return s;
}

std::vector<double> parseNumbers(const std::string& text, size_t expected, const std::string& section,
								 const std::string& k)
{
	std::istringstream is(text);
	std::vector<double> v;
	double x;
	while (is >> x) v.push_back(x);
	if (v.size() != expected || !is.eof())
		throw InputError("[" + section + "]", k, "expected " + std::to_string(expected) + " numbers, got '" + text + "'");
	return v;
}
}  // namespace

void writeTagsIniKeys(std::ostream& out, const std::vector<TagDetection>& tags)
{
	out << "tag_count=" << tags.size() << "\n";
	for (unsigned i = 1; i <= tags.size(); i++)
	{
		const auto& t = tags[i - 1];
		const Eigen::Vector3d p = t.position();
		const Eigen::Quaterniond q = t.quaternion();
		const double pose[7] = {p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z()};
		Eigen::Matrix<double, 6, 6, Eigen::RowMajor> cov = t.covariance;
		out << key(i, "family") << "=" << t.family << "\n"
			<< key(i, "id") << "=" << t.id << "\n"
			<< key(i, "size") << "=" << mrpt::format("%.17g", t.size) << "\n"
			<< key(i, "pose") << "=" << numbers(pose, 7) << "\n"
			<< key(i, "cov") << "=" << numbers(cov.data(), 36) << "\n";
	}
}

std::vector<TagDetection> readTagsIniKeys(const mrpt::config::CConfigFileBase& ini, const std::string& section)
{
	const int n = ini.read_int(section, "tag_count", 0);
	std::vector<TagDetection> tags;
	for (unsigned i = 1; i <= static_cast<unsigned>(std::max(n, 0)); i++)
	{
		TagDetection t;
		t.family = ini.read_string(section, key(i, "family"), "");
		if (t.family.empty()) throw InputError("[" + section + "]", key(i, "family"), "missing");
		t.id = ini.read_int(section, key(i, "id"), -1);
		t.size = ini.read_double(section, key(i, "size"), 0);
		if (t.id < 0 || !(t.size > 0)) throw InputError("[" + section + "]", key(i, "id"), "missing id or size");

		const auto pose = parseNumbers(ini.read_string(section, key(i, "pose"), ""), 7, section, key(i, "pose"));
		t.pose = Eigen::Isometry3d::Identity();
		t.pose.translation() = Eigen::Vector3d(pose[0], pose[1], pose[2]);
		t.pose.linear() = Eigen::Quaterniond(pose[3], pose[4], pose[5], pose[6]).normalized().toRotationMatrix();
		t.corners = cornersFromPose(t.pose, t.size);

		const std::string cov = ini.read_string(section, key(i, "cov"), "");
		if (!cov.empty())
		{
			const auto c = parseNumbers(cov, 36, section, key(i, "cov"));
			t.covariance = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(c.data());
		}
		tags.push_back(t);
	}
	return tags;
}

}  // namespace tagmap::mrpt_bridge
