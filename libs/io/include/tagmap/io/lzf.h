// LZF decompression (the codec of PCD "DATA binary_compressed"). Written
// from the format description, so malformed input is an error with a byte
// offset instead of a read or write out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace tagmap::io
{
struct LzfError : std::runtime_error
{
	LzfError(size_t inputOffset, const std::string& what) : std::runtime_error(what), offset(inputOffset) {}
	size_t offset;  // position in the compressed input where decoding failed
};

/** Decodes `in` into exactly `outLen` bytes at `out`. Throws LzfError when
 *  the stream is corrupt, refers before the start of the output, or does not
 *  produce exactly `outLen` bytes. */
void lzfDecompress(const uint8_t* in, size_t inLen, uint8_t* out, size_t outLen);

}  // namespace tagmap::io
