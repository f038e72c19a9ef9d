// libFuzzer target: the PCD reader (ascii, binary, binary_compressed).
#include "fuzz_point_cloud.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	tagmap::fuzz::loadPointCloudFrom(data, size, ".pcd");
	return 0;
}
