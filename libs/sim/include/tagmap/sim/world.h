// Ray casting against the scene's textured rectangles. Acceleration is a
// per-object axis-aligned box tested first (slab test), which is enough for
// scenes of tens to a few hundred objects: a box of six faces, a tag paper
// or a poster is skipped with one test when the ray misses it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
struct Hit
{
	double t = 0;  // distance along the (unit) ray
	float reflectivity = 0;  // texture value at the hit point, 0..1
	double cosIncidence = 0;  // |cos| between ray and surface normal
	int object = -1;  // index into the objects the World was built from
};

class World
{
   public:
	explicit World(const std::vector<SceneObject>& objects);

	/** Nearest hit with t in (tmin, tmax) of the ray o + t d, |d| = 1. */
	bool cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double tmin, double tmax, Hit& hit) const;

	size_t faceCount() const { return faces_.size(); }

   private:
	struct Face
	{
		Eigen::Vector3d c, ax, ay, n;
		double hw, hh;
		Texture texture;
		bool frontOnly;
		int object;
	};
	struct Bounds
	{
		Eigen::Vector3d lo, hi;
		size_t first, count;  // faces_[first, first + count)
	};
	std::vector<Face> faces_;
	std::vector<Bounds> bounds_;
};

}  // namespace tagmap::sim
