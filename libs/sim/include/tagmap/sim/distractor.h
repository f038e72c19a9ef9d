// High-contrast things that are NOT tags, to keep the detector honest:
// checkerboards (square, black/white, bordered like a tag), posters of random
// blocks (tag-like bit patterns without a valid code), text-like lines of
// blocks, lane stripes, and mirror-printed tags (a tag's bitmap flipped
// left-right: no valid code from the front, only seen from behind).
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
	MirroredTag
};

struct DistractorSpec
{
	std::string name;
	DistractorKind kind = DistractorKind::Checkerboard;
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // printed face, z out of it
	double width = 1, height = 1;  // sheet size, metres
	double cell = 0.05;  // checker square / block / character cell / stripe width, metres
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

}  // namespace tagmap::sim
