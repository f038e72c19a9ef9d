#include "tagmap/sim/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tagmap::sim
{
World::World(const std::vector<SceneObject>& objects)
{
	for (size_t oi = 0; oi < objects.size(); oi++)
	{
		Bounds b;
		b.first = faces_.size();
		b.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
		b.hi = -b.lo;
		for (const Rect& r : objects[oi].faces)
		{
			Face f;
			f.c = r.pose.translation();
			f.ax = r.pose.linear().col(0);
			f.ay = r.pose.linear().col(1);
			f.n = r.pose.linear().col(2);
			f.hw = r.halfW;
			f.hh = r.halfH;
			f.texture = r.texture;
			f.frontOnly = r.printedFrontOnly;
			f.object = static_cast<int>(oi);
			for (int sx : {-1, 1})
				for (int sy : {-1, 1})
				{
					const Eigen::Vector3d p = f.c + sx * f.hw * f.ax + sy * f.hh * f.ay;
					b.lo = b.lo.cwiseMin(p);
					b.hi = b.hi.cwiseMax(p);
				}
			faces_.push_back(std::move(f));
		}
		b.count = faces_.size() - b.first;
		// Pad so flat (zero-thickness) boxes still pass the slab test.
		b.lo.array() -= 1e-6;
		b.hi.array() += 1e-6;
		if (b.count) bounds_.push_back(b);
	}
}

bool World::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double tmin, double tmax, Hit& hit) const
{
	const Eigen::Vector3d inv = d.cwiseInverse();  // +-inf on axis-parallel rays is fine for slabs
	double best = tmax;
	const Face* bestFace = nullptr;
	double bestU = 0, bestV = 0;
	for (const Bounds& b : bounds_)
	{
		double t0 = tmin, t1 = best;
		for (int k = 0; k < 3; k++)
		{
			double ta = (b.lo[k] - o[k]) * inv[k];
			double tb = (b.hi[k] - o[k]) * inv[k];
			if (ta > tb) std::swap(ta, tb);
			// NaN (0 * inf when the origin lies on a slab plane) leaves t0/t1 unchanged.
			if (ta > t0) t0 = ta;
			if (tb < t1) t1 = tb;
		}
		if (t0 > t1) continue;
		for (size_t i = b.first; i < b.first + b.count; i++)
		{
			const Face& f = faces_[i];
			const double denom = d.dot(f.n);
			if (std::abs(denom) < 1e-12) continue;
			const double t = (f.c - o).dot(f.n) / denom;
			if (!(t > tmin && t < best)) continue;
			const Eigen::Vector3d p = o + t * d - f.c;
			const double u = p.dot(f.ax);
			if (std::abs(u) > f.hw) continue;
			const double v = p.dot(f.ay);
			if (std::abs(v) > f.hh) continue;
			best = t;
			bestFace = &f;
			bestU = u;
			bestV = v;
		}
	}
	if (!bestFace) return false;
	const double cosI = -d.dot(bestFace->n);  // > 0 when the front face is seen
	hit.t = best;
	hit.cosIncidence = std::abs(cosI);
	hit.reflectivity = (bestFace->frontOnly && cosI <= 0) ? bestFace->texture.base : bestFace->texture.at(bestU, bestV);
	hit.object = bestFace->object;
	return true;
}

}  // namespace tagmap::sim
