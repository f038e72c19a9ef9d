// index.html of a report: summary, the map picture, the detections table,
// stage timings, candidate images and the table of rejected clusters. A
// small inline script marks every <img> data-loaded="yes|no" and writes
// "all N images loaded" into #image-check (what the browser test looks for).
#pragma once

#include <string>
#include <vector>

#include "tagmap/report/report_input.h"

namespace tagmap::report
{
struct PageImages
{
	std::string topView;  // path relative to index.html
	std::string topViewCaption;
	struct Candidate
	{
		size_t index;  // into Detections::candidates
		std::string path;
	};
	std::vector<Candidate> candidates;  // in page order
	size_t candidatesOmitted = 0;  // had an image, not shown (ReportParams::maxCandidateImages)
};

std::string reportPage(const ReportInput& in, const PageImages& images, const ReportParams& p);

}  // namespace tagmap::report
