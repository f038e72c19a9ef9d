// High-contrast things that are NOT tags, to keep the detector honest:
// checkerboards (square, black/white, bordered like a tag), posters of random
// blocks (tag-like bit patterns without a valid code), text-like lines of
// blocks, lane stripes, mirror-printed tags (a tag's bitmap flipped
// left-right: no valid code from the front, only seen from behind), and the
// clutter of a city: facade window grids, zebra crossings, QR-like codes
// (finder squares, random modules) and black-bordered squares with a random
// interior that is provably no tag (the hardest negative).
#pragma once

#include <cstdint>
#include <string>

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
enum class DistractorKind
{
	Checkerboard,
	RandomBlocks,
	Text,
	Stripes,
	MirroredTag,
	WindowGrid,  // cell = window pitch: a pane 4/5 of it, mullions 1/5, light frame
	Zebra,  // cell = bar width = gap; light, worn bars along the sheet's height on dark asphalt
	QrLike,  // cell = module; 2-module quiet zone, three finder squares, timing rows, random modules
	BorderedSquare  // cell = cell; quiet zone and black border of one cell, random non-tag interior
};

struct DistractorSpec
{
	std::string name;
	DistractorKind kind = DistractorKind::Checkerboard;
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // printed face, z out of it
	double width = 1, height = 1;  // sheet size, metres
	double cell = 0.05;  // checker square / block / character cell / stripe width (see the kinds), metres
	double fill = 0.5;  // fraction of black blocks (RandomBlocks, Text)
	uint64_t seed = 1;  // pattern of RandomBlocks/Text (part of the scene, not of the run)
	float dark = 0.06f, light = 0.85f;
	double offset = 1e-4;  // standoff from the mounting surface
	/** MirroredTag: the tag whose bitmap is printed mirrored; the sheet is
	 *  its whole bitmap (width = height), so cell = width / bitmap cells. */
	std::string family;
	int id = 0;
};

SceneObject makeDistractor(const DistractorSpec& spec);

/** Whole cells of `cell` metres in `length`; a length meant as a whole
 *  number of cells (0.95 m of 0.05 m: 18.999999999999996 in floating
 *  point) counts them all. */
int cellsIn(double length, double cell);

/** Whole `cell`s a kind needs across its shorter side: a QR-like code's
 *  finders and quiet zone take 19, a bordered square 7 (3 x 3 interior),
 *  a window grid 2 (one window and its mullions); 0 for the other kinds. */
int minCellsAcross(DistractorKind kind);

}  // namespace tagmap::sim
