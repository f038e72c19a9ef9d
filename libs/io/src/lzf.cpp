#include "tagmap/io/lzf.h"

namespace tagmap::io
{
// LZF is a sequence of runs, each introduced by a control byte c:
//   c < 32:  a literal run of c + 1 bytes follows;
//   c >= 32: a back reference; length L = c >> 5 (7 means "7 + next byte"),
//            then one more byte completes the distance; it copies L + 2
//            bytes from 1 + ((c & 31) << 8 | that byte) bytes back.
// Back references may overlap the bytes they produce, so they are copied
// forward one byte at a time.
void lzfDecompress(const uint8_t* in, size_t inLen, uint8_t* out, size_t outLen)
{
	size_t ip = 0, op = 0;
	while (ip < inLen)
	{
		const size_t ctrlAt = ip;
		const unsigned ctrl = in[ip++];
		if (ctrl < 32)
		{
			const size_t len = ctrl + 1;
			if (len > inLen - ip) throw LzfError(ctrlAt, "literal run of " + std::to_string(len) + " bytes runs past the end of the compressed data");
			if (len > outLen - op) throw LzfError(ctrlAt, "literal run writes past the declared uncompressed size");
			for (size_t k = 0; k < len; ++k) out[op + k] = in[ip + k];
			ip += len;
			op += len;
			continue;
		}
		size_t len = ctrl >> 5;
		if (len == 7)
		{
			if (ip >= inLen) throw LzfError(ctrlAt, "back reference cut off by the end of the compressed data");
			len += in[ip++];
		}
		if (ip >= inLen) throw LzfError(ctrlAt, "back reference cut off by the end of the compressed data");
		const size_t distance = (((ctrl & 0x1fu) << 8) | in[ip++]) + 1;
		len += 2;
		if (distance > op) throw LzfError(ctrlAt, "back reference points before the start of the data");
		if (len > outLen - op) throw LzfError(ctrlAt, "back reference writes past the declared uncompressed size");
		const size_t from = op - distance;
		for (size_t k = 0; k < len; ++k) out[op + k] = out[from + k];
		op += len;
	}
	if (op != outLen)
		throw LzfError(inLen, "decompressed to " + std::to_string(op) + " bytes, header declares " + std::to_string(outLen));
}

}  // namespace tagmap::io
