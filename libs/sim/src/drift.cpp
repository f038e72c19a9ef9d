#include "tagmap/sim/drift.h"

#include <cmath>

#include "tagmap/sim/rng.h"

namespace tagmap::sim
{
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
		const Eigen::Isometry3d odom = steps[k - 1].truePose.inverse() * steps[k].truePose;
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
