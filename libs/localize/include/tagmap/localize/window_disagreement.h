// How much the scans of a merged window disagree about where a tag is.
//
// `observe --window N` moves the window's earlier scans into the current
// sensor frame with the odometry. The odometry drifts, so each earlier scan
// lands a little off, and a tag found in the merged points is off by their
// mean: 2-16 mm on the Livox run at window 3, while the detection's
// covariance, from the points alone, said 0.4-1.9 mm (tagmap-bench-observe:
// error over sigma 4-10 at the median). The scans themselves show the
// misregistration: along the tag's normal each scan's points give the
// plane's offset to a fraction of the range noise, and those offsets agree
// only as well as the scans were placed. That spread, less what the range
// noise alone would make of it, is taken as the misregistration in every
// direction (odometry drift has no preferred axis here), and added to the
// tag's position covariance. No odometry noise model is needed, and a
// window whose scans line up adds nothing.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
struct WindowDisagreementParams
{
	/** Points within this many surface-noise RMS of the tag's plane (and
	 *  inside its border square) are the tag's. */
	double slabNoises = 4;
	/** A scan with fewer points on the tag does not vote. */
	size_t minPointsPerScan = 10;
};

/** The misregistration (metres, one axis) of the scans of `merged` as seen
 *  on `tag`: the points-weighted spread of each scan's mean offset along the
 *  tag's normal, less the spread the range noise explains; 0 when fewer than
 *  two scans hold enough points. `scanStarts`: the first point of each scan
 *  in `merged`, increasing (the last scan runs to the end). `surfaceNoise`:
 *  the RMS of a flat surface in these points (Detections::surfaceNoise). */
double windowMisregistration(const TagDetection& tag, const mrpt::maps::CPointsMapXYZI& merged,
							 const std::vector<size_t>& scanStarts, double surfaceNoise,
							 const WindowDisagreementParams& params = {});

/** Adds `sigma`^2 to the variance of each axis of the tag's position. */
void addPositionUncertainty(TagDetection& tag, double sigma);

}  // namespace tagmap::localize
