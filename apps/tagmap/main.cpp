// tagmap: fiducial tags on 3D LiDAR maps. Dispatches to the sub-commands.
#include <cstring>
#include <iostream>
#include <string>

#include "commands.h"

namespace
{
struct Command
{
	const char* name;
	int (*run)(int, char**);
	const char* summary;
};

const Command kCommands[] = {
	{"detect", tagmap::app::runDetect, "find fiducial tags in a point-cloud map and write their poses"},
	{"simulate", tagmap::app::runSimulate, "simulate LiDAR maps of a YAML scene, with exact ground truth"},
	{"compare", tagmap::app::runCompare, "score a result file against ground truth (found, missed, errors)"},
	{"observe", tagmap::app::runObserve, "detect tags in each scan of a rawlog; add beacon ranges and tag poses"},
	{"localize", tagmap::app::runLocalize, "localize a LiDAR in a tag map (particle filter or direct), score it"},
	{"config", tagmap::app::runConfig, "print the effective detection parameters as YAML (--dump)"},
};

void printUsage(std::ostream& o)
{
	o << "Usage: tagmap <command> [options]   (tagmap <command> --help for details)\n\nCommands:\n";
	for (const auto& c : kCommands) o << "  " << c.name << std::string(12 - std::strlen(c.name), ' ') << c.summary << "\n";
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))
	{
		printUsage(argc < 2 ? std::cerr : std::cout);
		return argc < 2 ? 2 : 0;
	}
	if (!std::strcmp(argv[1], "--version"))
	{
		std::cout << "tagmap " << TAGMAP_VERSION << "\n";
		return 0;
	}
	for (const auto& c : kCommands)
		if (argv[1] == std::string(c.name)) return c.run(argc - 1, argv + 1);
	std::cerr << "tagmap: unknown command '" << argv[1] << "' (try tagmap --help)\n";
	return 2;
}
