// libFuzzer target: the PLY reader (ascii, binary little endian).
#include "fuzz_point_cloud.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	tagmap::fuzz::loadPointCloudFrom(data, size, ".ply");
	return 0;
}
