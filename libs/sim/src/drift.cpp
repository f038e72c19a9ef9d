#include "tagmap/sim/drift.h"

#include <cmath>

#include "tagmap/sim/rng.h"

namespace tagmap::sim
{
namespace
{
// The sensor's motion `odom` as a carrier with the step's systematic error
// would report it: the carrier's move (mount * odom * mount^-1) lengthened
// by the scale error and turned by the heading bias over its length.
Eigen::Isometry3d biased(const Eigen::Isometry3d& odom, const DriftStep& s)
{
	if (s.scaleError == 0 && s.headingBiasRadPerM == 0) return odom;
	Eigen::Isometry3d carrier = s.mount * odom * s.mount.inverse();
	const double dist = carrier.translation().norm();
	carrier.translation() *= 1 + s.scaleError;
	carrier.linear() = Eigen::AngleAxisd(s.headingBiasRadPerM * dist, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
					   carrier.linear();
	return s.mount.inverse() * carrier * s.mount;
}
}  // namespace

std::vector<Eigen::Isometry3d> driftPoses(const std::vector<DriftStep>& steps, const DriftParams& p, uint64_t seed)
{
	std::vector<Eigen::Isometry3d> out;
	out.reserve(steps.size());
	for (size_t k = 0; k < steps.size(); k++)
	{
		if (k == 0)
		{
			out.push_back(steps[0].truePose);
			continue;
		}
		const Eigen::Isometry3d odom = biased(steps[k - 1].truePose.inverse() * steps[k].truePose, steps[k]);
		const double dist = odom.translation().norm();
		const double dt = std::max(0.0, steps[k].seconds);
		const double s = steps[k].scale;
		const double sigT = s * std::sqrt(p.translationPerSqrtM * p.translationPerSqrtM * dist +
										  p.translationPerSqrtS * p.translationPerSqrtS * dt);
		const double degToRad = M_PI / 180.0;
		const double sigR = s * degToRad *
							std::sqrt(p.rotationDegPerSqrtM * p.rotationDegPerSqrtM * dist +
									  p.rotationDegPerSqrtS * p.rotationDegPerSqrtS * dt);
		Rng rng(streamSeed(seed, kStreamDrift, k));
		Eigen::Vector3d dt3, dr3;
		for (int i = 0; i < 3; i++) dt3[i] = sigT * gaussian(rng);
		for (int i = 0; i < 3; i++) dr3[i] = sigR * gaussian(rng);
		Eigen::Isometry3d noise = Eigen::Isometry3d::Identity();
		if (dr3.norm() > 0) noise.linear() = Eigen::AngleAxisd(dr3.norm(), dr3.normalized()).toRotationMatrix();
		noise.translation() = dt3;
		out.push_back(out.back() * odom * noise);
	}
	return out;
}

}  // namespace tagmap::sim
