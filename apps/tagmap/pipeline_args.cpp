#include "pipeline_args.h"

#include <cstdio>

#include "tagmap/tag_family.h"

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

PipelineParams pipelineParamsFromArgs(const cli::Args& args)
{
	PipelineParams params = args.has("--config") ? PipelineParams::fromYamlFile(args.get("--config")) : PipelineParams{};
	if (args.has("--family")) params.families = parseFamilyList(args.get("--family"));
	if (args.has("--tag-size"))
	{
		params.tagSize = args.getDouble("--tag-size", 0);
		if (!(params.tagSize > 0 && params.tagSize <= kMaxTagSize))
			throw cli::UsageError("--tag-size must be a positive length in metres, at most 10");
	}
	if (args.has("--threads"))
	{
		const long t = args.getInt("--threads", 0);
		if (t < 1 || t > 1024) throw cli::UsageError("--threads must be between 1 and 1024");
		params.threads = static_cast<unsigned>(t);
	}
	return params;
}

std::set<std::string> with(std::set<std::string> a, const std::set<std::string>& b)
{
	a.insert(b.begin(), b.end());
	return a;
}

}  // namespace tagmap::app
