// `tagmap observe`: every LiDAR scan of a rawlog gets, in its sensory frame
// (or right after it, in an observations-only rawlog), what the scan shows
// of the tags: a CObservationBeaconRanges (for MRPT's range-only tools) and
// a tagmap::obs::CObservationTagPoses (full relative 6-DoF poses).
#pragma once

#include <mrpt/obs/CRawlog.h>

#include <map>
#include <string>

#include "tagmap/count_progress.h"
#include "tagmap/localize/beacon_ranges.h"
#include "tagmap/pipeline.h"

namespace tagmap::localize
{
struct ObserveParams
{
	BeaconRangeParams ranges;
	/** Label suffix of the added observations: "<scan label>_tags" and
	 *  "<scan label>_ranges", so tools can pick them by label. */
	std::string tagsLabelSuffix = "_tags", rangesLabelSuffix = "_ranges";
	/** Scans merged before detecting: each scan with the window - 1 scans
	 *  before it, moved into its sensor frame by the rawlog's odometry
	 *  (rawlog_odometry.h). 1: every scan alone. A short Livox frame (0.1 s,
	 *  ~10 k points) holds too few points on a tag 4-10 m away to decode;
	 *  a window of a few frames fills it in, while the odometry's drift over
	 *  that time (cm/m) stays below the tag's cell size. Without odometry
	 *  in the rawlog a window > 1 is an error: the scans cannot be placed.
	 *  A merged tag's position covariance also carries how much the scans
	 *  disagree about it (window_disagreement.h). */
	size_t window = 1;
	/** Longest window: when `window` scans show no tag, the scan is detected
	 *  again merged with up to maxWindow - 1 scans before it. Most frames
	 *  keep the short window's small drift; those between tags, which a
	 *  short window leaves empty, get a sighting whose covariance says how
	 *  much more its scans disagree. 0 or <= window: no second try. */
	size_t maxWindow = 0;
};

/** One detection's cost: the points it ran on (the window merged) and the
 *  pipeline's own per-stage report. */
struct ScanTiming
{
	size_t points = 0;
	size_t scansMerged = 1;  // the window the reported detection ran on (maxWindow's when the short one saw nothing)
	double seconds = 0;  // Pipeline::detect alone (both windows' when the long one was tried), not reading or merging
	std::vector<StageReport> stages;
	std::vector<CandidateReport> candidates;  // where each candidate was and what became of it (no images)
};

struct ObserveReport
{
	size_t scans = 0;  // LiDAR observations processed
	size_t scansWithTags = 0;
	size_t scansWithTagsInLongWindow = 0;  // of those, seen only by maxWindow's second try
	size_t tagsSeen = 0;  // sum over scans
	size_t meanPointsDetected = 0;  // points per detection (the window's scans merged)
	/** Scans in which each tag ("family:id") was seen: is every tag of the
	 *  site observed somewhere along the run? */
	std::map<std::string, size_t> scansPerTag;
	std::vector<ScanTiming> perScan;  // one per scan, in rawlog order
	double seconds = 0;
	/** Median of perScan's seconds (0 without scans): the sensor rate the
	 *  detection keeps up with is 1 / this. */
	double medianDetectSeconds() const;
};

/** For a program that observes scans at sensor rate: keeps up to 64 MB of
 *  freed memory in the process for the next scan. Each detection allocates
 *  and frees the same few megabytes of images; by default glibc serves
 *  such blocks by mmap or returns them from the heap's top, and every scan
 *  faults the same pages in again (0.4 ms of a 10 ms scan on one core,
 *  docs/PERFORMANCE.md). Process-wide (mallopt): call it from `main`, not
 *  from a library; a no-op without glibc. */
void keepScanMemoryForReuse();

/** Returns a copy of `in` with the tag observations added. Observations
 *  without intensity are passed through untouched. `progress`: scans done
 *  and in all, after each scan. */
mrpt::obs::CRawlog observeRawlog(const mrpt::obs::CRawlog& in, const Pipeline& pipeline,
								 const ObserveParams& params = {}, ObserveReport* report = nullptr,
								 const CountProgressFn& progress = {});

}  // namespace tagmap::localize
