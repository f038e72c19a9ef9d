#include "tagmap/sim/beam_footprint.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tagmap::sim
{
BeamFootprint::BeamFootprint(const BeamParams& p, const IntensityModel& intensity) : p_(p), intensity_(intensity)
{
	// Ring radius at ~60 % of the half-divergence: for a Gaussian beam whose
	// divergence is quoted at 1/e^2 this puts the samples near the energy
	// centroid of the outer annulus, so centre + ring weigh about equally.
	// An elliptical beam scales the ring per axis (x horizontal, y vertical).
	const double rh = 0.6 * 0.5 * p.divergenceMrad * 1e-3;
	const double rv = 0.6 * 0.5 * p.divergenceVerticalMrad * 1e-3;
	for (int k = 0; k < p.subRays; k++)
	{
		const double a = 2 * M_PI * (k + 0.5) / p.subRays;
		ring_.emplace_back(rh * std::cos(a), rv * std::sin(a));
	}
}

void BeamFootprint::crossSection(const Eigen::Vector3d& d, const Eigen::Vector3d& up, Eigen::Vector3d& e1,
								 Eigen::Vector3d& e2) const
{
	// A circle needs no orientation: the fixed world-z helper keeps its
	// sample directions exactly as they always were (maps reproducible
	// across versions). An ellipse is fixed to the sensor: e1 horizontal
	// (perpendicular to the beam and the sensor's up), e2 towards up.
	const Eigen::Vector3d ref = p_.circular() ? Eigen::Vector3d::UnitZ() : up;
	// A beam along `ref` itself: any helper across it will do.
	const Eigen::Vector3d across = p_.circular() ? Eigen::Vector3d::UnitX() : ref.unitOrthogonal();
	const Eigen::Vector3d helper = std::abs(d.dot(ref)) < 0.9 ? ref : across;
	e1 = d.cross(helper).normalized();
	e2 = d.cross(e1);
}

bool BeamFootprint::measure(const World& world, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
							const Eigen::Vector3d& up, double minRange, double maxRange, Echo& echo) const
{
	struct Sub
	{
		double t, strength;
		int object;
	};
	constexpr int kMaxSub = 33;
	std::array<Sub, kMaxSub> subs;
	int n = 0;
	const int total = 1 + static_cast<int>(std::min<size_t>(ring_.size(), kMaxSub - 1));

	Hit h;
	if (world.cast(o, d, 0.0, maxRange, h))
		subs[n++] = {h.t, intensity_.returnStrength(h.reflectivity, h.cosIncidence), h.object};
	if (total > 1)
	{
		Eigen::Vector3d e1, e2;
		crossSection(d, up, e1, e2);
		for (int k = 0; k + 1 < total; k++)
		{
			const Eigen::Vector3d ds = (d + ring_[k].x() * e1 + ring_[k].y() * e2).normalized();
			// Sub-ray range projected on the centre ray: the echo time is what counts.
			if (world.cast(o, ds, 0.0, maxRange, h))
				subs[n++] = {h.t * ds.dot(d), intensity_.returnStrength(h.reflectivity, h.cosIncidence), h.object};
		}
	}
	if (n == 0) return false;

	// Echoes closer together than the mixing window merge; pick the strongest group.
	std::sort(subs.begin(), subs.begin() + n, [](const Sub& a, const Sub& b) { return a.t < b.t; });
	double bestStrength = -1, bestRange = 0;
	int bestObject = -1;
	for (int i = 0; i < n;)
	{
		int j = i;
		double s = 0, st = 0, strongest = -1;
		int obj = -1;
		while (j < n && subs[j].t - subs[i].t <= p_.mixingWindow)
		{
			s += subs[j].strength;
			st += subs[j].strength * subs[j].t;
			if (subs[j].strength > strongest)
			{
				strongest = subs[j].strength;
				obj = subs[j].object;
			}
			j++;
		}
		if (s > bestStrength)
		{
			bestStrength = s;
			bestRange = s > 0 ? st / s : subs[i].t;
			bestObject = obj;
		}
		i = j;
	}
	echo.strength = bestStrength / total;
	echo.range = bestRange;
	echo.object = bestObject;
	if (echo.range < minRange || echo.range > maxRange) return false;
	return intensity_.detected(echo.strength, echo.range);
}

}  // namespace tagmap::sim
