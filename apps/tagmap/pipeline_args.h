// The options that set detection parameters, shared by `tagmap detect` and
// `tagmap config --dump` so both read them the same way: defaults, then
// --config FILE, then the flags.
#pragma once

#include <set>
#include <string>

#include "cli.h"
#include "tagmap/pipeline_params.h"

namespace tagmap::app
{
/** --config, --family, --tag-size, --threads (value options for cli::parse). */
const std::set<std::string>& pipelineOptions();

/** Their --help lines, defaults included. */
std::string pipelineOptionsHelp();

/** Throws cli::UsageError for bad flag values, InputError for a bad file. */
PipelineParams pipelineParamsFromArgs(const cli::Args& args);

/** `a` and `b` together, for cli::parse(). */
std::set<std::string> with(std::set<std::string> a, const std::set<std::string>& b);

}  // namespace tagmap::app
