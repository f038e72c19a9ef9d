// Stage 3 (paper, Sec. II-D): keep clusters whose box could hold a tag.
// Criterion 1 (size): the box diagonal in the tag plane lies between the
// tag's side (box aligned with the tag) and its diagonal (box at 45 deg);
// Criterion 2 (squareness): length / width <= 1.5. We also require the
// cluster to be flat, since a tag is paper on a surface.
#pragma once

#include <optional>
#include <vector>

#include "tagmap/clustering.h"
#include "tagmap/verdict.h"

namespace tagmap
{
struct CandidateFilterParams
{
	double tagSize = 0;  // metres; 0 = unknown, use [minTagSize, maxTagSize]
	double minTagSize = 0.10;
	double maxTagSize = 1.50;
	double maxAspect = 1.5;  // criterion 2
	/** A tag's edge points may miss part of the border (sparse or occluded
	 *  scans): accept a box this much smaller than the smallest tag. */
	double shortfall = 0.15;
	/** Upper size bound, as a multiple of the paper's (2a): a tag printed on
	 *  a board or poster with contrasty edges clusters together with them,
	 *  and such a box still holds the tag. Decoding and the pattern check
	 *  reject what is not a tag, so a generous bound costs only time. */
	double maxOversize = 2.0;
	/** Flatness: the box's robust height (OrientedBox::thickness) at most
	 *  this fraction of its width, plus twice the noise allowance. */
	double maxFlatness = 0.35;
	/** Boxes rejected by squareness but at most this elongated are tried
	 *  again as square windows along their length (squareWindows). */
	double splitAspect = 4.0;
};

/** Nothing when the box may hold a tag, else the reason: Verdict::Size,
 *  Squareness or NotFlat. `band` is how far the kept edge points reach
 *  beyond the tag border (the gradient radius), `noise` how far a flat
 *  surface's points stray from its plane (from the map's measured surface
 *  noise, DerivedLengths::planeNoise). */
std::optional<Verdict> rejectCandidate(const OrientedBox& box, double band, double noise, const CandidateFilterParams& p);

/** Criterion 1's upper bound alone: the box is too large to hold any tag
 *  asked for, even printed on a board (a rejectCandidate() Verdict::Size). */
bool tooLargeForATag(const OrientedBox& box, double band, const CandidateFilterParams& p);

/** The same box to within `tolerance` (metres): centres, the four corners
 *  of the face and the heights each that close, whichever way either box's
 *  axes point. Two candidates whose boxes differ by less than a point
 *  spacing gather the same points into the same image. */
bool sameBox(const OrientedBox& a, const OrientedBox& b, double tolerance);

/** Square boxes of `box`'s width, half-overlapping along its length, for a
 *  box too elongated for a tag: a tag clustered together with an edge
 *  beside it (a pillar's corner, a shelf) lies in one of them. Up to
 *  splitAspect every window; longer (a pillar from floor to roof) only the
 *  windows holding at least 3x the median number of the cluster's points,
 *  given as their offsets `along` the box's length from its centre. Empty
 *  when the width itself could hold no tag. */
std::vector<OrientedBox> squareWindows(const OrientedBox& box, double band, double noise, const CandidateFilterParams& p,
									 const std::vector<double>& along = {});

}  // namespace tagmap
