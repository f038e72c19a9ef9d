// Stage 4-6's schedule: which candidates are decoded, by which worker, in
// what order. Several candidates (the clusterings at two tolerances, the
// density levels) are often one tag's: on the Livox windows of `observe`
// each tag was decoded 3.7 times, and the merge kept one of them. A
// candidate centred on a tag that a candidate of its group already decoded
// is not decoded again, nor are the outlines and reads on such a tag in a
// larger box around it. What is skipped depends only on the candidates
// before it in its group, and a group is decoded by one worker in a fixed
// order (the driver's: the largest cluster first): the result is the same
// for any thread count.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "tagmap/clustering.h"
#include "tagmap/tag_detection.h"

namespace tagmap
{
/** The boxes as groups of nearly the same centre: two boxes whose centres
 *  are closer than half the narrower one's width are in one group, and
 *  so is any chain of such pairs (connected components). Each group in
 *  ascending index, the groups in order of their first index. Boxes of
 *  one tag (its clusters at two tolerances and density levels) are
 *  centred on it; boxes that merely overlap (a window grid's panes, the
 *  square windows along a wall, a large box over several small ones) are
 *  not joined, so the groups stay small enough to share among threads. */
std::vector<std::vector<size_t>> concentricBoxGroups(const std::vector<OrientedBox>& boxes);

/** True when `point` (a candidate box's centre, an outline's or a read's
 *  centre on its image) lies on `tag`: within half the tag's size of its
 *  centre (the merge's "one square", merge_detections.h: a read there would
 *  be that tag again or lose to it). A box centred there was proposed for
 *  the tag; whatever else its image shows lies off the tag, and is still
 *  read there. */
bool onDecodedTag(const Eigen::Vector3d& point, const TagDetection& tag);

}  // namespace tagmap
