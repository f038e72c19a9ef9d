// tagmap config --dump: the effective detection parameters as YAML, to see
// what a run will use and to start a configuration file from.
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "pipeline_args.h"

namespace tagmap::app
{
namespace
{
std::string usage()
{
	return "Usage: tagmap config --dump [--config FILE] [--family F[,F...]] [--tag-size S] [--threads N]\n"
		   "\n"
		   "Prints the detection parameters `tagmap detect` would use with the same options, as\n"
		   "YAML: the defaults, overridden by --config FILE, overridden by the flags. Save it,\n"
		   "edit it and pass it back with `tagmap detect --config FILE`; every parameter is\n"
		   "explained in share/config/default.yaml and docs/TUNING.md.\n"
		   "\n"
		   "Options:\n"
		   "  --dump             print the effective configuration to stdout (required)\n" +
		   pipelineOptionsHelp() + "  --help             this text\n";
}
}  // namespace

int runConfig(int argc, char** argv)
{
	return cli::runCommand("config", [&] {
		const cli::Args args = cli::parse(argc, argv, 1, pipelineOptions(), {"--dump", "--help"});
		if (args.has("--help"))
		{
			std::cout << usage();
			return 0;
		}
		if (!args.positional.empty()) throw cli::UsageError("unexpected argument '" + args.positional[0] + "'");
		if (!args.has("--dump")) throw cli::UsageError("nothing to do: use --dump");
		pipelineParamsFromArgs(args).toYaml().printAsYAML(std::cout);
		return 0;
	});
}

}  // namespace tagmap::app
