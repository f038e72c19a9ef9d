// The sub-commands of `tagmap`. Each lives in its own cmd_*.cpp, parses its
// arguments and calls the library; none holds algorithmic code.
#pragma once

namespace tagmap::app
{
// argv[0] is the sub-command name; return the process exit status.
int runSimulate(int argc, char** argv);
int runDetect(int argc, char** argv);
int runConfig(int argc, char** argv);
int runCompare(int argc, char** argv);
int runObserve(int argc, char** argv);
int runLocalize(int argc, char** argv);
}  // namespace tagmap::app
