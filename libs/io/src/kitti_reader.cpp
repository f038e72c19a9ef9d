// KITTI Velodyne .bin: bare little-endian float32 records "x y z i", no
// header, so the file size is the only check there is.
#include "reader_common.h"
#include "readers.h"

namespace tagmap::io::detail
{
void readKitti(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const FileBytes bytes(path);
	constexpr size_t record = 4 * sizeof(float);
	if (bytes.size() == 0) throw InputError(path, "", "file is empty");
	if (bytes.size() % record != 0)
		throw InputError(path, byteAt(bytes.size() - bytes.size() % record),
						 "file size " + std::to_string(bytes.size()) + " is not a multiple of 16 bytes (x y z i float32 records): truncated or not a KITTI scan");
	report.format = "kitti";
	report.intensityField = "i";
	MapFiller fill(out, report);
	Column c[4];
	for (size_t a = 0; a < 4; ++a) c[a] = Column{Scalar::F32, bytes.data() + a * sizeof(float), record};
	extractColumns(c, bytes.size() / record, fill);
	fill.finish();
}

}  // namespace tagmap::io::detail
