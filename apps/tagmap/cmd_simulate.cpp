#include <iostream>

#include "commands.h"

namespace tagmap::app
{
int runSimulate(int, char**)
{
	std::cerr << "tagmap simulate: not implemented yet\n";
	return 1;
}
}  // namespace tagmap::app
