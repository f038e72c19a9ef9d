// libFuzzer target: the scene YAML parser (tagmap simulate's input), from
// text as loadScene() does after reading the file. Any text either gives a
// scene or throws InputError.
#include <string>

#include "tagmap/errors.h"
#include "tagmap/sim/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string text(reinterpret_cast<const char*>(data), size);
	try
	{
		tagmap::sim::parseScene(text, "fuzz.yaml");
	}
	catch (const tagmap::InputError&)
	{
	}
	return 0;
}
