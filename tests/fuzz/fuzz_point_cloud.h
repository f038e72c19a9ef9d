// Shared body of the point-cloud reader fuzzers: any bytes either load or
// throw InputError; anything else (another exception, a crash, a sanitizer
// report, a huge allocation) is a bug.
#pragma once

#include <cmath>
#include <cstdlib>

#include "fuzz_input_file.h"
#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"

namespace tagmap::fuzz
{
inline void loadPointCloudFrom(const uint8_t* data, size_t size, const char* ext)
{
	const std::string& path = writeInputFile(data, size, ext);
	io::LoadReport report;
	mrpt::maps::CPointsMapXYZI map;
	try
	{
		io::loadPointCloud(path, map, &report);
	}
	catch (const InputError&)
	{
		return;
	}
	// What loaded must keep the LoadReport's promises.
	if (report.pointsKept != map.size() ||
		report.pointsKept + report.nonFiniteSkipped + report.outOfRangeSkipped != report.pointsRead)
		std::abort();
	for (size_t k = 0; k < map.size(); ++k)
	{
		float x, y, z;
		map.getPoint(k, x, y, z);
		if (!(std::fabs(x) <= io::kMaxAbsCoordinate && std::fabs(y) <= io::kMaxAbsCoordinate &&
			  std::fabs(z) <= io::kMaxAbsCoordinate))
			std::abort();
	}
}

}  // namespace tagmap::fuzz
