// The detection settings a run uses, resolved in one place from, in order:
// the caller's defaults (the built-in PipelineParams, or another set such as
// localize's single-scan parameters), a YAML config file that replaces them,
// and the user's explicit choices (families, tag size, threads) on top.
// `tagmap detect`, `tagmap config --dump`, `tagmap observe` and CTagMap's
// [MetricMap] ini options all go through it, so they cannot disagree.
#pragma once

#include <string>

#include "tagmap/pipeline_params.h"

namespace tagmap
{
/** What a user chose; empty or zero means "not chosen". */
struct DetectionChoices
{
	std::string configFile;  // YAML over the built-in defaults (share/config/default.yaml)
	std::string families;  // "tag36h11,aruco_4x4_50"
	double tagSize = 0;  // metres
	unsigned threads = 0;
};

/** `defaults`, or the config file read over the built-in defaults when one
 *  is given; then the chosen families, tag size and threads. Throws
 *  InputError for an unreadable or invalid file, std::invalid_argument for
 *  an unknown family or a value out of range (PipelineParams::validate). */
PipelineParams resolveDetectionSettings(const DetectionChoices& choices,
										const PipelineParams& defaults = PipelineParams{});

}  // namespace tagmap
