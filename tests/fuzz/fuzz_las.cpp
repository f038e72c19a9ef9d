// libFuzzer target: the LAS reader (1.0-1.4, point formats 0-10).
#include "fuzz_point_cloud.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	tagmap::fuzz::loadPointCloudFrom(data, size, ".las");
	return 0;
}
