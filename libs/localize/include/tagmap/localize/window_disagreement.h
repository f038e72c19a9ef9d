// How much the scans of a merged window disagree about where a tag is.
//
// `observe --window N` moves the window's earlier scans into the current
// sensor frame with the odometry. The odometry drifts, so each earlier scan
// lands a little off, and a tag found in the merged points is off by their
// mean: 2-16 mm on the Livox run at window 3, while the detection's
// covariance, from the points alone, said 0.4-1.9 mm (tagmap-bench-observe:
// error over sigma 4-10 at the median). The scans themselves show the
// misregistration, each axis where the scan's points measure it:
//   - along the tag's normal, each scan's points give the plane's offset
//     (their mean distance from the tag's plane);
//   - in the tag's plane, each scan's points alone are fitted to the tag's
//     bitmap from the merged pose (pattern_refinement.h), which gives the
//     scan's shift with its own covariance (scans whose points fit the
//     bitmap worse than a detected tag must do not vote).
// The readings agree only as well as the scans were placed: their spread
// beyond what each one's own variance explains (the between-scan variance
// of a random-effects model, DerSimonian-Laird) is the misregistration.
// The merged tag is off from the current scan's frame by the mean of the
// older scans' offsets, which grow with their age like a random walk: the
// spread is scaled to that mean's variance (driftOverSpread in the .cpp)
// and added to the tag's position covariance in its own frame. No odometry
// noise model is needed, and a window whose scans line up adds nothing.
//
// Misplaced scans also turn the merged tag: where each scan covers a
// different part of it (a rosette's petals), offsets along the normal tilt
// the fitted plane and shifts in the plane turn the fitted pattern. The
// turn is propagated from the same spreads through a least-squares fit of
// the tag's points with each scan moved as a whole (tiltAndTurn in the
// .cpp): a scan covering the whole tag tilts nothing, two halves a tag
// width apart tilt it by their offset over half that width. A heading drift turns the
// tag only by itself, a tenth of the translation it causes at a few metres'
// range, and is left out. The fits' own turns are not used: on the car
// park's sparse frames they scattered by 5-16 deg, far beyond both their
// own covariance and any drift.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
struct WindowDisagreementParams
{
	/** Points within this many surface-noise RMS of the tag's plane (and
	 *  inside its grid) are the tag's. */
	double slabNoises = 4;
	/** A scan with fewer points on the tag does not vote (the pattern fit
	 *  needs 20 to mean anything). */
	size_t minPointsPerScan = 20;
};

/** Standard deviations of the merged tag's misregistration, in the tag's frame. */
struct WindowMisregistration
{
	double alongNormal = 0;  // metres
	double inPlaneX = 0, inPlaneY = 0;  // metres, along the tag's x and y
	/** What those offsets turn the merged tag by: covariance of the small
	 *  rotation about the tag's x, y and z (its normal), radians^2. */
	Eigen::Matrix3d rotation = Eigen::Matrix3d::Zero();
	int scansCompared = 0;  // scans with enough points on the tag
};

/** The misregistration of the scans of `merged` as seen on `tag` (its pose
 *  in `merged`'s frame); all 0 when fewer than two scans hold enough points.
 *  `scanStarts`: the first point of each scan in `merged`, increasing (the
 *  last scan runs to the end); the current scan first, then the earlier
 *  ones oldest first, as observe merges them (a scan's age is its drift).
 *  `surfaceNoise`: the RMS of a flat surface in these points
 *  (Detections::surfaceNoise). */
WindowMisregistration windowMisregistration(const TagDetection& tag, const mrpt::maps::CPointsMapXYZI& merged,
											const std::vector<size_t>& scanStarts, double surfaceNoise,
											const WindowDisagreementParams& params = {});

/** Adds the misregistration's variances to the tag's position and rotation
 *  covariance, rotated from the tag's frame into the frame its pose maps into. */
void addMisregistration(TagDetection& tag, const WindowMisregistration& m);

}  // namespace tagmap::localize
