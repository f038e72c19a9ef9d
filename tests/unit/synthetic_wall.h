// A tiny synthetic map for unit tests of the pipeline stages: a flat wall
// sampled on a jittered grid with one printed tag on it. Not the simulator
// (that is libs/sim): no sensor model, just geometry and the true bitmap.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <cmath>
#include <random>

#include "tagmap/tag_detection.h"
#include "tagmap/tag_family.h"

namespace tagmap::testing
{
struct WallScene
{
	std::string family = "tag36h11";
	int id = 7;
	double size = 0.2;
	double spacing = 0.006;  // metres between samples
	double wall = 0.8;  // wall edge, metres
	double noise = 0.001;  // metres, along the normal
	double intensityNoise = 0.02;  // reflectivity units (paper 0.85, ink 0.06, wall 0.5)
	double intensityScale = 1.0;
	Eigen::Isometry3d T_G_wall = Eigen::Isometry3d::Identity();  // wall plane is its z = 0
	double tagRotation = 0.0;  // in-plane, radians
	/** Horizontal intensity bands over everything, `stripes` added on every
	 *  other band of `stripePeriod / 2` metres: what a wall merged from scan
	 *  lines at different ranges shows. 0: none. */
	double stripes = 0.0, stripePeriod = 0.03;
	unsigned seed = 1;
};

inline mrpt::maps::CPointsMapXYZI makeWall(const WallScene& s, TagDetection& truth)
{
	const TagBitmap bm = renderTagBitmap(s.family, s.id);
	const double cell = s.size / bm.borderCells;
	const double centre = bm.borderStart + bm.borderCells / 2.0;
	std::mt19937 rng(s.seed);
	std::normal_distribution<double> n01(0, 1);
	std::uniform_real_distribution<double> jitter(-0.3, 0.3);
	mrpt::maps::CPointsMapXYZI map;
	const double c = std::cos(s.tagRotation), sn = std::sin(s.tagRotation);
	for (double y = -s.wall / 2; y <= s.wall / 2; y += s.spacing)
		for (double x = -s.wall / 2; x <= s.wall / 2; x += s.spacing)
		{
			const double px = x + jitter(rng) * s.spacing, py = y + jitter(rng) * s.spacing;
			// Tag frame coordinates (tag rotated in the wall plane by tagRotation).
			const double tx = c * px + sn * py, ty = -sn * px + c * py;
			const int col = static_cast<int>(std::floor(tx / cell + centre));
			const int row = static_cast<int>(std::floor(-ty / cell + centre));
			double refl = 0.5;  // wall
			if (std::abs(tx) < 0.5 * s.size + 2 * cell && std::abs(ty) < 0.5 * s.size + 2 * cell) refl = 0.85;  // paper
			if (row >= 0 && col >= 0 && row < bm.cells && col < bm.cells) refl = bm.at(row, col) ? 0.85 : 0.06;
			// Every other half period, counted from y = 0 (floor keeps the parity right below it).
			const bool oddBand = s.stripes > 0 && static_cast<long>(std::floor(2 * py / s.stripePeriod)) % 2 != 0;
			const double band = oddBand ? s.stripes : 0.0;
			const double I = (refl + band + s.intensityNoise * n01(rng)) * s.intensityScale;
			const Eigen::Vector3d p = s.T_G_wall * Eigen::Vector3d(px, py, s.noise * n01(rng));
			// insertPointRGB stores the R channel as the intensity, unclamped.
			map.insertPointRGB(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()),
							   static_cast<float>(I), 0, 0);
		}
	truth.family = s.family;
	truth.id = s.id;
	truth.size = s.size;
	Eigen::Isometry3d T_wall_tag = Eigen::Isometry3d::Identity();
	T_wall_tag.linear() = Eigen::AngleAxisd(s.tagRotation, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	truth.pose = s.T_G_wall * T_wall_tag;
	truth.corners = cornersFromPose(truth.pose, s.size);
	return map;
}

/** `s`'s wall 2 m in front of the origin (a sensor there), its printed face
 *  towards it: wall x to the sensor's right (-y), wall y up. */
inline mrpt::maps::CPointsMapXYZI makeWallInFrontOfTheOrigin(WallScene s, TagDetection& truth)
{
	s.T_G_wall.linear().col(0) = -Eigen::Vector3d::UnitY();
	s.T_G_wall.linear().col(1) = Eigen::Vector3d::UnitZ();
	s.T_G_wall.linear().col(2) = -Eigen::Vector3d::UnitX();
	s.T_G_wall.translation() = Eigen::Vector3d(2, 0.1, 0.2);
	return makeWall(s, truth);
}

}  // namespace tagmap::testing
