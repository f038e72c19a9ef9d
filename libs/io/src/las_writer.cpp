// LAS writer (ASPRS LAS 1.2 for point formats 0-3, 1.4 otherwise): X Y Z
// as int32 counts of `scale` around a whole-metre offset, the intensity in
// 16 bits; every other field zero, one return per pulse. Used by
// `tagmap simulate --las` to make test maps, shifted into georeferenced
// coordinates with --shift.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "las_format.h"
#include "tagmap/atomic_file.h"
#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
namespace
{
template <typename T>
void put(std::vector<char>& buf, size_t at, T v)
{
	std::memcpy(buf.data() + at, &v, sizeof(T));
}
}  // namespace

void saveLas(const std::string& path, const mrpt::maps::CPointsMapXYZI& map, const LasWriteParams& p)
{
	namespace las = detail::las;
	if (p.pointFormat < 0 || p.pointFormat > las::kMaxPointFormat)
		throw std::invalid_argument("LAS point format " + std::to_string(p.pointFormat) + " does not exist (0 to 10)");
	if (!(p.scale > 0)) throw std::invalid_argument("LAS scale must be positive");
	const size_t n = map.size();
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto& is = map.getPointsBufferRef_intensity();

	double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
	for (size_t i = 0; i < n; ++i)
	{
		const double q[3] = {xs[i] + p.shift.x(), ys[i] + p.shift.y(), zs[i] + p.shift.z()};
		for (int a = 0; a < 3; ++a)
		{
			lo[a] = i ? std::min(lo[a], q[a]) : q[a];
			hi[a] = i ? std::max(hi[a], q[a]) : q[a];
		}
	}
	double offset[3];
	for (int a = 0; a < 3; ++a)
	{
		offset[a] = std::round(0.5 * (lo[a] + hi[a]));
		if ((hi[a] - offset[a]) / p.scale > std::numeric_limits<int32_t>::max() - 1 ||
			(offset[a] - lo[a]) / p.scale > std::numeric_limits<int32_t>::max() - 1)
			throw std::invalid_argument("the map spans more than int32 LAS counts of " + std::to_string(p.scale) + " m");
	}
	// Intensities stretched to the 16 bits: the simulator's are 0..1, and
	// the pipeline divides by the map's own intensity spread anyway.
	float maxI = 0;
	for (size_t i = 0; i < n; ++i) maxI = std::max(maxI, is[i]);
	const double toU16 = maxI > 0 ? 65535.0 / maxI : 1.0;

	const bool v14 = p.pointFormat > 3;
	const size_t headerSize = las::minHeaderSize(v14 ? 4 : 2);
	const size_t record = las::pointRecordSize(p.pointFormat);
	std::vector<char> header(headerSize, 0);
	std::memcpy(header.data(), "LASF", 4);
	// Formats 6-10 require the WKT bit (global encoding bit 4) in LAS 1.4.
	put<uint16_t>(header, las::kGlobalEncoding, p.pointFormat >= 6 ? 16 : 0);
	put<uint8_t>(header, las::kVersionMajor, 1);
	put<uint8_t>(header, las::kVersionMinor, v14 ? 4 : 2);
	std::memcpy(header.data() + 26, "tagmap", 6);  // system identifier
	std::memcpy(header.data() + 58, "tagmap simulate", 15);  // generating software
	put<uint16_t>(header, las::kHeaderSize, static_cast<uint16_t>(headerSize));
	put<uint32_t>(header, las::kOffsetToPoints, static_cast<uint32_t>(headerSize));
	put<uint32_t>(header, las::kVlrCount, 0);
	put<uint8_t>(header, las::kPointFormat, static_cast<uint8_t>(p.pointFormat));
	put<uint16_t>(header, las::kRecordLength, static_cast<uint16_t>(record));
	// Legacy counts: 0 for formats 6-10 (LAS 1.4), and when they overflow.
	const bool legacy = p.pointFormat < 6 && n <= std::numeric_limits<uint32_t>::max();
	put<uint32_t>(header, las::kLegacyCount, legacy ? static_cast<uint32_t>(n) : 0);
	put<uint32_t>(header, las::kLegacyByReturn, legacy ? static_cast<uint32_t>(n) : 0);
	for (int a = 0; a < 3; ++a)
	{
		put<double>(header, las::kScale + 8 * a, p.scale);
		put<double>(header, las::kOffset + 8 * a, offset[a]);
		put<double>(header, las::kMaxMin + 16 * a, hi[a]);
		put<double>(header, las::kMaxMin + 16 * a + 8, lo[a]);
	}
	if (v14)
	{
		put<uint64_t>(header, las::kCount64, n);
		put<uint64_t>(header, las::kByReturn64, n);
	}

	writeFileAtomically(path, [&](std::ostream& out) {
		out.write(header.data(), static_cast<std::streamsize>(header.size()));
		constexpr size_t chunk = 1 << 14;
		std::vector<char> buf(record * std::min(n, chunk));
		for (size_t first = 0; first < n; first += chunk)
		{
			const size_t count = std::min(chunk, n - first);
			std::fill(buf.begin(), buf.end(), 0);
			for (size_t k = 0; k < count; ++k)
			{
				const size_t i = first + k, at = k * record;
				const double q[3] = {xs[i] + p.shift.x(), ys[i] + p.shift.y(), zs[i] + p.shift.z()};
				for (int a = 0; a < 3; ++a)
					put<int32_t>(buf, at + 4 * a, static_cast<int32_t>(std::llround((q[a] - offset[a]) / p.scale)));
				put<uint16_t>(buf, at + las::kIntensityAt,
							  static_cast<uint16_t>(std::clamp(std::lround(is[i] * toU16), 0L, 65535L)));
				// Return 1 of 1: 3+3 bits in formats 0-5, 4+4 bits in 6-10.
				put<uint8_t>(buf, at + 14, p.pointFormat < 6 ? 0x09 : 0x11);
			}
			out.write(buf.data(), static_cast<std::streamsize>(count * record));
		}
	});
}

}  // namespace tagmap::io
