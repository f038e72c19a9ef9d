#include <cmath>

#include "scene_yaml_parts.h"

namespace tagmap::sim
{
const std::set<std::string> kPoseKeys = {"position", "rpy_deg", "quaternion", "normal", "up", "roll_deg", "look_at"};

namespace
{
constexpr double kDeg = M_PI / 180.0;

Eigen::Vector3d unitVector(const YamlReader& r, const std::string& key)
{
	const Eigen::Vector3d v = r.vec3(key);
	if (v.norm() < 1e-9) r.child(key).fail("must not be a zero vector");
	return v.normalized();
}

// Frame with the given z axis and y as close as possible to `up`.
Eigen::Matrix3d frameFromZ(const Eigen::Vector3d& z, Eigen::Vector3d up, const YamlReader& r)
{
	if (std::abs(up.dot(z)) > 0.999) r.fail("'up' must not be parallel to the normal");
	const Eigen::Vector3d y = (up - up.dot(z) * z).normalized();
	Eigen::Matrix3d R;
	R.col(0) = y.cross(z);
	R.col(1) = y;
	R.col(2) = z;
	return R;
}
}  // namespace

Eigen::Isometry3d parsePose(const YamlReader& r)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = r.vec3("position");
	int forms = 0;
	for (const char* k : {"rpy_deg", "quaternion", "normal", "look_at"}) forms += r.has(k);
	if (forms > 1) r.fail("give only one of rpy_deg, quaternion, normal, look_at");
	if (r.has("rpy_deg"))
	{
		const Eigen::Vector3d a = r.vec3("rpy_deg") * kDeg;
		T.linear() = (Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()) *
					  Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) *
					  Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()))
						 .toRotationMatrix();
	}
	else if (r.has("quaternion"))
	{
		const auto q = r.numbers("quaternion", 4);
		Eigen::Quaterniond Q(q[0], q[1], q[2], q[3]);
		if (Q.norm() < 1e-9) r.child("quaternion").fail("must not be zero");
		T.linear() = Q.normalized().toRotationMatrix();
	}
	else if (r.has("normal"))
	{
		const Eigen::Vector3d z = unitVector(r, "normal");
		Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
		if (r.has("up"))
			up = unitVector(r, "up");
		else if (std::abs(z.z()) > 0.9)
			up = Eigen::Vector3d::UnitX();  // floors and ceilings: pattern "up" along +x
		T.linear() = frameFromZ(z, up, r) * Eigen::AngleAxisd(r.number("roll_deg", 0) * kDeg, Eigen::Vector3d::UnitZ());
	}
	else if (r.has("look_at"))
	{
		const Eigen::Vector3d x = r.vec3("look_at") - T.translation();
		if (x.norm() < 1e-9) r.child("look_at").fail("must differ from position");
		const Eigen::Vector3d xn = x.normalized();
		Eigen::Vector3d y = Eigen::Vector3d::UnitZ().cross(xn);
		if (y.norm() < 1e-6) y = Eigen::Vector3d::UnitY();  // looking straight up/down
		y.normalize();
		T.linear().col(0) = xn;
		T.linear().col(1) = y;
		T.linear().col(2) = xn.cross(y);
	}
	if ((r.has("up") || r.has("roll_deg")) && !r.has("normal")) r.fail("'up' and 'roll_deg' need 'normal'");
	return T;
}

}  // namespace tagmap::sim
