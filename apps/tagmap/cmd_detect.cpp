#include <iostream>

#include "commands.h"

namespace tagmap::app
{
int runDetect(int, char**)
{
	std::cerr << "tagmap detect: not implemented yet\n";
	return 1;
}
}  // namespace tagmap::app
