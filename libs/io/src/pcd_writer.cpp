// Binary PCD v0.7 writer: x y z intensity as float32 records.
#include <algorithm>
#include <ostream>
#include <vector>

#include "tagmap/atomic_file.h"
#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
void savePcdBinary(const std::string& path, const mrpt::maps::CPointsMapXYZI& map)
{
	const size_t n = map.size();
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto& is = map.getPointsBufferRef_intensity();
	writeFileAtomically(path, [&](std::ostream& out) {
		out << "# .PCD v0.7 - Point Cloud Data file format\n"
			   "VERSION 0.7\n"
			   "FIELDS x y z intensity\n"
			   "SIZE 4 4 4 4\n"
			   "TYPE F F F F\n"
			   "COUNT 1 1 1 1\n"
			<< "WIDTH " << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\nDATA binary\n";
		// Interleave through a bounded buffer: a few MB regardless of map size.
		constexpr size_t chunk = 1 << 16;
		std::vector<float> buffer(4 * std::min(n, chunk));
		for (size_t first = 0; first < n; first += chunk)
		{
			const size_t count = std::min(chunk, n - first);
			for (size_t k = 0; k < count; ++k)
			{
				buffer[4 * k + 0] = xs[first + k];
				buffer[4 * k + 1] = ys[first + k];
				buffer[4 * k + 2] = zs[first + k];
				buffer[4 * k + 3] = is[first + k];
			}
			out.write(reinterpret_cast<const char*>(buffer.data()), static_cast<std::streamsize>(count * 4 * sizeof(float)));
		}
	});
}

}  // namespace tagmap::io
