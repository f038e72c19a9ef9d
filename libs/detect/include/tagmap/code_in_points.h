// Stage 6b, after the fit: which of a decoded tag's cells did a point measure?
// The decoders read an image rendered from the points. Where the points lie
// about a cell apart (a far tag in a single scan), many of the image's cells
// are interpolated between points around them, and a real tag's smeared
// bits can read as another code of its family: `tagmap observe` reported
// tag36h11:422 on tag 0, 6.9 m from a 64-beam scanner (pattern fit 0.92,
// libapriltag counted 2 wrong bits over all 36; 6 of them held no point at
// the fitted pose, and over the other 30 that read is chance, P = 2.0e-3).
// A cell no point measured is no evidence, however clearly the image shows
// it: the read's cell values (ReadEvidence::cells, from the image it was
// read on) are judged again (read_evidence.h: the chance budget, the border
// ring, the quiet zone) with those cells erased; and the points' own read,
// cell by cell, must be nearer the decoded code than any other
// (codeDistances: that 422 read is 1 bit from 422, 0 from tag 0).
#pragma once

#include <vector>

#include "tagmap/intermediate_plane.h"
#include "tagmap/tag_detection.h"

namespace tagmap
{
/** For each cell of t's grid at its (fitted) pose and size, row-major as the
 *  family's bitmap: the mean intensity of the plane's inlier points that
 *  fall in it, NaN where none does. (Counting only points in a cell's
 *  middle, away from where a footprint straddles two cells, lost 13 of 120
 *  and 7 of 45 sightings of tagmap-bench-observe; any point in the cell, 1
 *  and 1.) */
std::vector<float> cellMeansFromPoints(const TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys,
									   const float* zs, const float* is);

/** `cells` (a read's cell values) with those no point measured (NaN in
 *  `pointMeans`) set to NaN: erasures for judgeCells(). */
std::vector<float> eraseUnmeasured(std::vector<float> cells, const std::vector<float>& pointMeans);

}  // namespace tagmap
