// Stage 6b: refine and verify a decoded tag against its own bitmap.
// Once the family and id are known, the printed pattern is known exactly
// (libapriltag / OpenCV bitmap). Fitting it to the intensities of all the
// tag's points, rather than to four image corners, uses thousands of
// measurements instead of four: the in-plane position and rotation get
// several times more accurate, and the correlation of points and pattern
// rejects decodes that are not really there (false positives on posters).
#pragma once

#include "tagmap/intermediate_plane.h"
#include "tagmap/tag_detection.h"

namespace tagmap
{
struct PatternRefinementParams
{
	bool refine = true;  // false: keep the decoder's corners, only verify
	/** Reject a decode whose points correlate less than this with its
	 *  bitmap: their means over bins a third of a cell wide (a sensor's
	 *  intensity noise per point averages out there, a wrong pattern does
	 *  not). TagDetection::patternFit stays the per-point correlation. */
	double minPatternFit = 0.6;
	int iterations = 12;
	/** Let the size float too (when --tag-size is not given). */
	bool estimateSize = true;
};

/** Updates t.pose, t.corners, t.size (if estimated), t.patternFit and the
 *  in-plane part of t.covariance. Returns false when the pattern does not fit. */
bool refineWithPattern(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs,
					   const float* is, const PatternRefinementParams& p);

/** The same fit with the family's frame as the pattern (frameBitmap():
 *  the black border ring and the white quiet zone, the code cells grey),
 *  so the tag's grid is placed by what every code of its family prints
 *  alike. A read's cells sampled on that grid are as fair a test of any
 *  code as on the decoder's own quad: the placement cannot have favoured
 *  the code read. Updates t as refineWithPattern() does (t.patternFit is
 *  the frame's fit); false with too few points on the grid. */
bool placeByFrame(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs,
				  const float* is, const PatternRefinementParams& p);

}  // namespace tagmap
