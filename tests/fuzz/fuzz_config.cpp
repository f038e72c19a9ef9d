// libFuzzer target: the detection configuration loader (--config FILE).
// Any file either gives parameters that pass validate() or throws InputError.
#include <cstdlib>

#include "fuzz_input_file.h"
#include "tagmap/errors.h"
#include "tagmap/pipeline_params.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = tagmap::fuzz::writeInputFile(data, size, ".yaml");
	try
	{
		const tagmap::PipelineParams p = tagmap::PipelineParams::fromYamlFile(path);
		p.validate();  // throws std::invalid_argument -> a bug: loading must have refused it
	}
	catch (const tagmap::InputError&)
	{
	}
	return 0;
}
