// What a report is made of (one detection run) and how much of it to show.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <string>

#include "tagmap/pipeline.h"
#include "tagmap/report/candidate_view.h"
#include "tagmap/report/top_view.h"

namespace tagmap::report
{
struct ReportInput
{
	std::string inputPath;  // the map file, as the user named it
	std::string inputSummary;  // e.g. "pcd-binary, intensity from 'intensity'"
	std::string commandLine;  // how to reproduce the run
	const mrpt::maps::CPointsMapXYZI& map;
	const Detections& found;  // from Pipeline::detect(..., keepImages = true)
	const PipelineParams& params;
};

struct ReportParams
{
	/** Candidate images on the page, decoded ones first, then the biggest
	 *  clusters; a city-block map can have thousands of candidates. */
	size_t maxCandidateImages = 300;
	/** Rows in the table of clusters without an image, biggest first. */
	size_t maxRejectedListed = 200;
	TopViewParams topView;
	CandidateViewParams candidate;
};

}  // namespace tagmap::report
