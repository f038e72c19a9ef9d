#include "tagmap/sim/tag_paper.h"

#include <algorithm>
#include <cmath>

#include "tagmap/sim/rng.h"
#include "tagmap/tag_detection.h"
#include "tagmap/tag_family.h"

namespace tagmap::sim
{
namespace
{
bool hasBoard(const TagSpec& s) { return s.boardWidth > 0 && s.boardHeight > 0; }
}  // namespace

Eigen::Isometry3d printedTagPose(const TagSpec& spec, uint64_t seed, size_t tagIndex)
{
	Eigen::Isometry3d T = spec.pose;
	if (spec.jitterDeg > 0)
	{
		Rng rng(streamSeed(seed, kStreamScene, tagIndex));
		std::uniform_real_distribution<double> u(-spec.jitterDeg * M_PI / 180, spec.jitterDeg * M_PI / 180);
		const double rx = u(rng), ry = u(rng), rz = u(rng);
		const bool tilt = hasBoard(spec);
		const Eigen::Matrix3d turn = (Eigen::AngleAxisd(rz, Eigen::Vector3d::UnitZ()) *
									  Eigen::AngleAxisd(tilt ? ry : 0.0, Eigen::Vector3d::UnitY()) *
									  Eigen::AngleAxisd(tilt ? rx : 0.0, Eigen::Vector3d::UnitX()))
										 .toRotationMatrix();
		T.linear() = T.linear() * turn;
		// A tilted board leans on the wall: its back corner nearest the wall
		// touches it, none goes through it (turned about its centre alone, a
		// 0.9 m board tilted 4 degrees sinks 3 cm into the wall, and the
		// wall then hides part of the tag).
		if (tilt)
		{
			double sunk = 0;
			for (double x : {-0.5, 0.5})
				for (double y : {-0.5, 0.5})
					sunk = std::max(sunk, -(turn * Eigen::Vector3d(x * spec.boardWidth, y * spec.boardHeight, 0)).z());
			T.translation() += spec.pose.linear().col(2) * sunk;
		}
	}
	T.translate(Eigen::Vector3d(0, 0, (hasBoard(spec) ? spec.boardStandoff : 0.0) + spec.paperOffset));
	return T;
}

SceneObject makeTagPaper(const TagSpec& spec, const Eigen::Isometry3d& printedPose)
{
	const TagBitmap bm = renderTagBitmap(spec.family, spec.id);
	const double cell = spec.size / bm.borderCells;
	// Grid placed so the border square is centred on the tag origin.
	const double centre = bm.centreInCells() * cell;
	Rect r;
	r.pose = printedPose;
	r.printedFrontOnly = true;
	r.texture.base = spec.white;
	r.texture.cols = r.texture.rows = bm.cells;
	r.texture.cellW = r.texture.cellH = cell;
	r.texture.left = -centre;
	r.texture.top = centre;
	r.texture.cells.resize(bm.pixels.size());
	for (size_t i = 0; i < bm.pixels.size(); i++) r.texture.cells[i] = bm.pixels[i] ? spec.white : spec.black;
	const double extent = std::max(centre, bm.cells * cell - centre);
	r.halfW = r.halfH = extent + spec.margin;

	SceneObject o;
	o.name = tagLabel(spec.family, spec.id);
	o.kind = ObjectKind::Tag;
	o.faces.push_back(std::move(r));
	if (hasBoard(spec))
	{
		// The board's front face, just behind the paper, and its four edges
		// reaching back to the wall (a slab `boardStandoff` thick).
		const double hw = 0.5 * spec.boardWidth, hh = 0.5 * spec.boardHeight, t = spec.boardStandoff;
		Eigen::Isometry3d front = printedPose;
		front.translate(Eigen::Vector3d(0, 0, -spec.paperOffset));
		Rect face;
		face.pose = front;
		face.halfW = hw;
		face.halfH = hh;
		face.texture.base = spec.boardReflectivity;
		o.faces.push_back(face);
		for (int axis = 0; axis < 2; axis++)
			for (int sgn : {-1, 1})
			{
				Eigen::Matrix3d R;  // edge frame: normal along +-x (or +-y) of the board
				const Eigen::Vector3d n = sgn * Eigen::Vector3d::Unit(axis);
				R.col(2) = n;
				R.col(1) = Eigen::Vector3d::UnitZ();
				R.col(0) = R.col(1).cross(R.col(2));
				Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
				local.linear() = R;
				local.translation() = n * (axis == 0 ? hw : hh) + Eigen::Vector3d(0, 0, -0.5 * t);
				Rect edge = face;
				edge.pose = front * local;
				edge.halfW = axis == 0 ? hh : hw;
				edge.halfH = 0.5 * t;
				o.faces.push_back(edge);
			}
	}
	return o;
}

TagDetection tagTruth(const TagSpec& spec, const Eigen::Isometry3d& printedPose)
{
	TagDetection d;
	d.family = spec.family;
	d.id = spec.id;
	d.size = spec.size;
	d.pose = printedPose;
	d.corners = cornersFromPose(printedPose, spec.size);
	return d;
}

}  // namespace tagmap::sim
