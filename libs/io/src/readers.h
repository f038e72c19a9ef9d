// One reader per format, each appending to `out` and filling `report`; the
// dispatch by extension lives in load_point_cloud.cpp. Private to tagmap_io.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <string>

#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io::detail
{
void readPcd(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readPly(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readKitti(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readXyziText(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readSimplemap(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readLas(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);
void readRawlog(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report);

}  // namespace tagmap::io::detail
