// Stage 7: one result per physical tag. Overlapping candidates, both
// readings of a mirror-ambiguous family and views from different boxes may
// decode the same tag; keep the best-supported reading of each.
#pragma once

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
/** Merges detections whose centres are closer than half the tag size:
 *  the same family and id is a duplicate; a different one at the same
 *  place is a conflicting reading and the better pattern fit wins.
 *  The result is sorted by family, id, then position (deterministic). */
std::vector<TagDetection> mergeDetections(std::vector<TagDetection> found);

}  // namespace tagmap
