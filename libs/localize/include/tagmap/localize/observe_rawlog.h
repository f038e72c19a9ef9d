// `tagmap observe`: every LiDAR scan of a rawlog gets, in its sensory frame
// (or right after it, in an observations-only rawlog), what the scan shows
// of the tags: a CObservationBeaconRanges (for MRPT's range-only tools) and
// a tagmap::obs::CObservationTagPoses (full relative 6-DoF poses).
#pragma once

#include <mrpt/obs/CRawlog.h>

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
};

struct ObserveReport
{
	size_t scans = 0;  // LiDAR observations processed
	size_t scansWithTags = 0;
	size_t tagsSeen = 0;  // sum over scans
	double seconds = 0;
};

/** Returns a copy of `in` with the tag observations added. Observations
 *  without intensity are passed through untouched. `progress`: scans done
 *  and in all, after each scan. */
mrpt::obs::CRawlog observeRawlog(const mrpt::obs::CRawlog& in, const Pipeline& pipeline,
								 const ObserveParams& params = {}, ObserveReport* report = nullptr,
								 const CountProgressFn& progress = {});

}  // namespace tagmap::localize
