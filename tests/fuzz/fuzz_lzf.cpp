// libFuzzer target: the LZF decoder on its own, fed directly (it takes a
// buffer). The first 4 bytes choose the declared output size, as the PCD
// header does; the decoder must stay inside both buffers whatever they say.
#include <cstring>
#include <memory>

#include "tagmap/io/lzf.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	if (size < 4) return 0;
	uint32_t outLen;
	std::memcpy(&outLen, data, 4);
	outLen %= 1u << 20;  // the reader bounds it by 88 x input; keep runs fast
	// Exact-size heap buffers, so ASan sees any byte read or written outside.
	const size_t inLen = size - 4;
	std::unique_ptr<uint8_t[]> in(new uint8_t[inLen]);
	std::memcpy(in.get(), data + 4, inLen);
	std::unique_ptr<uint8_t[]> out(new uint8_t[outLen]);
	try
	{
		tagmap::io::lzfDecompress(in.get(), inLen, out.get(), outLen);
	}
	catch (const tagmap::io::LzfError& e)
	{
		if (e.offset > inLen) __builtin_trap();  // the offset must point into the input
	}
	return 0;
}
