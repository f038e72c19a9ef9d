// Stage 7: one result per physical tag. Overlapping candidates, both
// readings of a mirror-ambiguous family and views from different boxes may
// decode the same tag; a square may also read as two different codes.
#pragma once

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
struct MergeParams
{
	/** Two different codes read on one square: the better pattern fit is
	 *  kept only when it beats the other by this many standard errors of
	 *  the difference of their correlations (Fisher z, from the points each
	 *  fit used); closer than that, the square is ambiguous and neither is
	 *  reported. 3: a tie passes as a clear winner about once in 700. */
	double conflictSigmas = 3.0;
};

/** Merges detections of one physical tag:
 *  - a read whose centre lies inside a larger detected tag's square (a
 *    code read into part of a bigger one) is dropped;
 *  - detections whose centres are closer than half the larger size are
 *    one square: the same family and id is a duplicate (the best pattern
 *    fit is kept); a different code is a conflicting reading, kept only
 *    when its fit clearly beats every other (MergeParams::conflictSigmas);
 *    so is the same code facing the other way when it is its own mirror
 *    image (isOwnMirrorImage(): its side is unknown from the code).
 *  The result is sorted by family, id, then position (deterministic). */
std::vector<TagDetection> mergeDetections(std::vector<TagDetection> found, const MergeParams& p = {});

}  // namespace tagmap
