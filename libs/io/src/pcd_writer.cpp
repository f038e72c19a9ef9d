// Binary PCD v0.7 writer: x y z intensity as float32 records, or x y z as
// float64 when the map is written shifted into georeferenced coordinates.
#include <algorithm>
#include <cstring>
#include <ostream>
#include <vector>

#include "tagmap/atomic_file.h"
#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
namespace
{
// Interleaves the records (x y z as Xyz, intensity as float) through a
// bounded buffer: a few MB regardless of map size.
template <typename Xyz>
void writeRecords(std::ostream& out, const mrpt::maps::CPointsMapXYZI& map, const Eigen::Vector3d& shift)
{
	const size_t n = map.size();
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto& is = map.getPointsBufferRef_intensity();
	constexpr size_t chunk = 1 << 16, record = 3 * sizeof(Xyz) + sizeof(float);
	std::vector<char> buffer(record * std::min(n, chunk));
	for (size_t first = 0; first < n; first += chunk)
	{
		const size_t count = std::min(chunk, n - first);
		for (size_t k = 0; k < count; ++k)
		{
			const size_t i = first + k;
			// In double, then to Xyz: a float plus a zero shift is the float itself.
			const Xyz v[3] = {static_cast<Xyz>(xs[i] + shift.x()), static_cast<Xyz>(ys[i] + shift.y()),
							  static_cast<Xyz>(zs[i] + shift.z())};
			std::memcpy(buffer.data() + k * record, v, sizeof(v));
			std::memcpy(buffer.data() + k * record + sizeof(v), &is[i], sizeof(float));
		}
		out.write(buffer.data(), static_cast<std::streamsize>(count * record));
	}
}
}  // namespace

void savePcdBinary(const std::string& path, const mrpt::maps::CPointsMapXYZI& map, const Eigen::Vector3d& shift)
{
	const size_t n = map.size();
	const bool f8 = !shift.isZero();
	writeFileAtomically(path, [&](std::ostream& out) {
		out << "# .PCD v0.7 - Point Cloud Data file format\n"
			   "VERSION 0.7\n"
			   "FIELDS x y z intensity\n"
			<< (f8 ? "SIZE 8 8 8 4\n" : "SIZE 4 4 4 4\n") << "TYPE F F F F\nCOUNT 1 1 1 1\n"
			<< "WIDTH " << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\nDATA binary\n";
		if (f8) writeRecords<double>(out, map, shift);
		else writeRecords<float>(out, map, shift);
	});
}

}  // namespace tagmap::io
