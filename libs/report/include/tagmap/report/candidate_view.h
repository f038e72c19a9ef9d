// One candidate cluster's intermediate-plane image as the decoders saw it,
// enlarged for people, with every decode drawn: the quad, its vertex indices
// 0..3 (the vertex order of docs/RESULT_FORMAT.md) and "family:id", green when the decode became a
// tag, orange when the pattern check rejected it.
#pragma once

#include <opencv2/core.hpp>

#include "tagmap/pipeline.h"

namespace tagmap::report
{
struct CandidateViewParams
{
	int minEdge = 240;  // small images are enlarged (nearest neighbour: pixels stay honest)
	int maxEdge = 480;  // large ones shrunk, so a page of hundreds stays light
};

/** BGR image; empty when the candidate has no image (rejected by the filter,
 *  not planar, or the run did not keep images). */
cv::Mat renderCandidateView(const CandidateReport& c, const CandidateViewParams& p = {});

}  // namespace tagmap::report
