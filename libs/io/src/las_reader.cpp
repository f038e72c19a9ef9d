// LAS 1.0-1.4 reader (ASPRS specification), point data record formats 0-10.
// X Y Z are int32 counts of a per-axis scale plus an offset: they are
// combined in double (X * scale + offset) and handed to the MapFiller, which
// subtracts the local origin before anything becomes float. Variable-length
// records are skipped through the header's offset to the point data;
// extended VLRs (after the points) and extra bytes per record are ignored.
#include <cmath>
#include <cstring>

#include "las_format.h"
#include "reader_common.h"
#include "readers.h"

namespace tagmap::io::detail
{
namespace
{
template <typename T>
T field(const FileBytes& bytes, size_t at)
{
	T v;
	std::memcpy(&v, bytes.data() + at, sizeof(T));
	return v;
}

struct LasHeader
{
	int minor = 0;
	int format = 0;
	size_t recordLength = 0;
	uint64_t offsetToPoints = 0;
	uint64_t count = 0;
	double scale[3] = {1, 1, 1};
	double offset[3] = {0, 0, 0};
};

LasHeader parseHeader(const std::string& path, const FileBytes& bytes)
{
	const std::string hdr = "header";
	if (bytes.size() == 0) throw InputError(path, "", "empty file");
	if (bytes.size() < 4 || std::memcmp(bytes.data(), "LASF", 4) != 0)
		throw InputError(path, hdr, "not a LAS file (no 'LASF' signature)");
	if (bytes.size() < las::minHeaderSize(0))
		throw InputError(path, hdr, "truncated: " + std::to_string(bytes.size()) + " bytes, a LAS header has at least 227");
	LasHeader h;
	const int major = field<uint8_t>(bytes, las::kVersionMajor);
	h.minor = field<uint8_t>(bytes, las::kVersionMinor);
	if (major != 1 || h.minor > 4)
		throw InputError(path, hdr, "LAS version " + std::to_string(major) + "." + std::to_string(h.minor) +
										 " is not supported (1.0 to 1.4 are)");
	const size_t headerSize = field<uint16_t>(bytes, las::kHeaderSize);
	if (headerSize < las::minHeaderSize(h.minor) || headerSize > bytes.size())
		throw InputError(path, hdr,
						 "bad header size " + std::to_string(headerSize) + " (LAS 1." + std::to_string(h.minor) +
							 " needs at least " + std::to_string(las::minHeaderSize(h.minor)) + ", the file has " +
							 std::to_string(bytes.size()) + " bytes)");
	const uint8_t formatByte = field<uint8_t>(bytes, las::kPointFormat);
	if (formatByte & las::kCompressedBits)
		throw InputError(path, hdr,
						 "compressed (LAZ) point data is not read; decompress it first, e.g. with 'laszip -i IN -o OUT.las' "
						 "or 'pdal translate IN OUT.las'");
	h.format = formatByte;
	if (h.format > las::kMaxPointFormat)
		throw InputError(path, hdr, "unknown point data record format " + std::to_string(h.format) + " (0 to 10 are defined)");
	h.recordLength = field<uint16_t>(bytes, las::kRecordLength);
	if (h.recordLength < las::pointRecordSize(h.format))
		throw InputError(path, hdr,
						 "point record length " + std::to_string(h.recordLength) + " is shorter than format " +
							 std::to_string(h.format) + "'s " + std::to_string(las::pointRecordSize(h.format)) + " bytes");
	h.offsetToPoints = field<uint32_t>(bytes, las::kOffsetToPoints);
	if (h.offsetToPoints < headerSize || h.offsetToPoints > bytes.size())
		throw InputError(path, hdr,
						 "offset to point data " + std::to_string(h.offsetToPoints) + " is outside the file (header " +
							 std::to_string(headerSize) + " bytes, file " + std::to_string(bytes.size()) + " bytes)");
	// LAS 1.4 keeps a 64-bit count (formats 6-10 must leave the legacy one
	// 0); older files and 1.4 writers of formats 0-5 may fill only the legacy one.
	h.count = field<uint32_t>(bytes, las::kLegacyCount);
	if (h.minor >= 4)
		if (const uint64_t c64 = field<uint64_t>(bytes, las::kCount64); c64 != 0) h.count = c64;
	const uint64_t room = (bytes.size() - h.offsetToPoints) / h.recordLength;
	if (h.count > room)
		throw InputError(path, hdr,
						 "point count " + std::to_string(h.count) + " is larger than the file holds (" +
							 std::to_string(room) + " records of " + std::to_string(h.recordLength) + " bytes)");
	for (int a = 0; a < 3; ++a)
	{
		h.scale[a] = field<double>(bytes, las::kScale + 8 * a);
		h.offset[a] = field<double>(bytes, las::kOffset + 8 * a);
		if (!std::isfinite(h.scale[a]) || h.scale[a] == 0 || !std::isfinite(h.offset[a]))
			throw InputError(path, hdr, std::string("bad ") + "XYZ"[a] + " scale or offset (" + std::to_string(h.scale[a]) +
											 ", " + std::to_string(h.offset[a]) + ")");
	}
	return h;
}
}  // namespace

void readLas(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const FileBytes bytes(path);
	const LasHeader h = parseHeader(path, bytes);
	report.format = "las-1." + std::to_string(h.minor) + "-format-" + std::to_string(h.format);
	report.intensityField = "intensity";
	MapFiller fill(out, report);
	fill.expect(static_cast<size_t>(h.count));
	const char* rec = bytes.data() + h.offsetToPoints;
	for (uint64_t k = 0; k < h.count; ++k, rec += h.recordLength)
	{
		int32_t xyz[3];
		std::memcpy(xyz, rec, sizeof(xyz));
		uint16_t intensity;
		std::memcpy(&intensity, rec + las::kIntensityAt, sizeof(intensity));
		fill.add(xyz[0] * h.scale[0] + h.offset[0], xyz[1] * h.scale[1] + h.offset[1], xyz[2] * h.scale[2] + h.offset[2],
				 intensity);
	}
	fill.finish();
}

}  // namespace tagmap::io::detail
