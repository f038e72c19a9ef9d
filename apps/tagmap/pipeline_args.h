// The options that set detection parameters, shared by `tagmap detect`,
// `tagmap config --dump` and `tagmap observe` so all read them the same way:
// the flags become DetectionChoices, resolveDetectionSettings() does the rest.
#pragma once

#include <set>
#include <string>

#include "cli.h"
#include "tagmap/detection_settings.h"

namespace tagmap::app
{
/** --config, --family, --tag-size, --threads (value options for cli::parse). */
const std::set<std::string>& pipelineOptions();

/** Their --help lines, defaults included. */
std::string pipelineOptionsHelp();

/** The flags as choices. Throws cli::UsageError for bad flag values. */
DetectionChoices detectionChoicesFromArgs(const cli::Args& args);

/** resolveDetectionSettings(detectionChoicesFromArgs(args), defaults):
 *  throws cli::UsageError for bad flag values, InputError for a bad file. */
PipelineParams pipelineParamsFromArgs(const cli::Args& args, const PipelineParams& defaults = PipelineParams{});

/** `a` and `b` together, for cli::parse(). */
std::set<std::string> with(std::set<std::string> a, const std::set<std::string>& b);

}  // namespace tagmap::app
