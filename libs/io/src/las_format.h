// The ASPRS LAS 1.0-1.4 public header block and point record layouts
// (LAS 1.4 R15, tables 3-4 and 7-17), shared by the reader and the writer so
// the offsets are written down once. Private to tagmap_io.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace tagmap::io::detail::las
{
// Byte offsets in the public header block (little-endian).
constexpr size_t kVersionMajor = 24, kVersionMinor = 25;
constexpr size_t kGlobalEncoding = 6;
constexpr size_t kHeaderSize = 94;  // u16
constexpr size_t kOffsetToPoints = 96;  // u32
constexpr size_t kVlrCount = 100;  // u32
constexpr size_t kPointFormat = 104;  // u8 (bits 6-7: LAZ compression)
constexpr size_t kRecordLength = 105;  // u16
constexpr size_t kLegacyCount = 107;  // u32
constexpr size_t kLegacyByReturn = 111;  // u32[5]
constexpr size_t kScale = 131;  // f64[3]
constexpr size_t kOffset = 155;  // f64[3]
constexpr size_t kMaxMin = 179;  // f64 max x, min x, max y, min y, max z, min z
constexpr size_t kWaveformStart = 227;  // u64, LAS 1.3+
constexpr size_t kEvlrStart = 235, kEvlrCount = 243;  // u64, u32, LAS 1.4
constexpr size_t kCount64 = 247;  // u64, LAS 1.4
constexpr size_t kByReturn64 = 255;  // u64[15], LAS 1.4

/** Smallest header each minor version defines: 227 (1.0-1.2), 235 (1.3), 375 (1.4). */
constexpr size_t minHeaderSize(int minor) { return minor >= 4 ? 375 : minor == 3 ? 235 : 227; }

constexpr int kMaxPointFormat = 10;
constexpr uint8_t kCompressedBits = 0xC0;  // set by LASzip in the format byte

/** Bytes of point data record format f (0..10) without extra bytes; X Y Z
 *  are int32 at 0, 4, 8 and intensity a uint16 at 12 in every format. */
constexpr size_t pointRecordSize(int f)
{
	constexpr size_t sizes[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
	return sizes[f];
}
constexpr size_t kIntensityAt = 12;

}  // namespace tagmap::io::detail::las
