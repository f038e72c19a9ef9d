// A printed tag as the simulator sees it: a sheet of white paper carrying
// the family's canonical bitmap (renderTagBitmap, never drawn by hand), and
// its exact ground truth.
#pragma once

#include <cstdint>

#include "tagmap/sim/scene.h"
#include "tagmap/tag_detection.h"

namespace tagmap::sim
{
/** Pose of the printed face (the ground truth T_G_tag): the mounting pose,
 *  turned by the seed-dependent jitter about the tag centre, then moved
 *  paperOffset along the tag's z so the paper lies in front of its wall. */
Eigen::Isometry3d printedTagPose(const TagSpec& spec, uint64_t seed, size_t tagIndex);

/** The paper rectangle with the bitmap texture, printed face at `printedPose`. */
SceneObject makeTagPaper(const TagSpec& spec, const Eigen::Isometry3d& printedPose);

/** Ground truth in the result schema (docs/RESULT_FORMAT.md) (corners in vertex-index order). */
TagDetection tagTruth(const TagSpec& spec, const Eigen::Isometry3d& printedPose);

}  // namespace tagmap::sim
