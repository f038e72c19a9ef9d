#include "pipeline_args.h"

#include <cstdio>


namespace tagmap::app
{
const std::set<std::string>& pipelineOptions()
{
	static const std::set<std::string> s = {"--config", "--family", "--tag-size", "--threads"};
	return s;
}

std::string pipelineOptionsHelp()
{
	const PipelineParams d;
	char sizes[160];
	std::snprintf(sizes, sizeof sizes, "any size in [%.2f, %.2f] m", d.candidates.minTagSize,
				  d.candidates.maxTagSize);
	return std::string(
			   "  --family F[,F...]  families to look for: tag36h11, tag25h9, tag16h5,\n"
			   "                     tagStandard41h12, ..., aruco_4x4_50, ... (default: all supported)\n"
			   "  --tag-size S       tag border-square edge in metres (default: ") +
		   sizes +
		   ",\n"
		   "                     candidates.min_tag_size..max_tag_size)\n"
		   "  --config FILE      YAML parameters, every one explained in share/config/default.yaml;\n"
		   "                     the flags above override it (default: built-in defaults)\n"
		   "  --threads N        worker threads; results do not depend on N (default: all cores)\n";
}

DetectionChoices detectionChoicesFromArgs(const cli::Args& args)
{
	DetectionChoices c;
	c.configFile = args.get("--config");
	c.families = args.get("--family");
	if (args.has("--tag-size"))
	{
		// Checked here too, so the message names the flag (a usage error), not a YAML key.
		c.tagSize = args.getDouble("--tag-size", 0);
		if (!(c.tagSize > 0 && c.tagSize <= kMaxTagSize))
			throw cli::UsageError("--tag-size must be a positive length in metres, at most 10");
	}
	if (args.has("--threads"))
	{
		const long t = args.getInt("--threads", 0);
		if (t < 1 || t > 1024) throw cli::UsageError("--threads must be between 1 and 1024");
		c.threads = static_cast<unsigned>(t);
	}
	return c;
}

PipelineParams pipelineParamsFromArgs(const cli::Args& args, const PipelineParams& defaults)
{
	return resolveDetectionSettings(detectionChoicesFromArgs(args), defaults);
}

std::set<std::string> with(std::set<std::string> a, const std::set<std::string>& b)
{
	a.insert(b.begin(), b.end());
	return a;
}

}  // namespace tagmap::app
