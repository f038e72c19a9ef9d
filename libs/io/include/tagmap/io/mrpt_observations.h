// Turning one MRPT observation into XYZI points in the map frame. Shared by
// the .simplemap reader and any reader of rawlogs, so each observation type
// is converted the same way everywhere.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include "tagmap/io/point_cloud_io.h"

namespace tagmap::io
{
/**
 * Appends the points of `obs` to `out`, placed at robotPose (+) sensorPose.
 * Understood: CObservationPointCloud holding a CPointsMapXYZI,
 * CObservationVelodyneScan (its point_cloud, generated from the raw packets
 * when empty; intensity 0..255), CObservation3DRangeScan with a range and an
 * intensity image (intensity 0..255, the gray level at the point's
 * pixel; points outside the intensity image count as non-finite).
 * CObservationRotatingScan is not: MRPT 2.5.8 stores no per-ring elevation
 * for it, so its range image cannot be turned into 3D points.
 * Returns false (and adds nothing) for observations without usable
 * intensity; non-finite points are skipped and counted in `report`.
 */
bool appendObservationToMap(const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& robotPose,
							mrpt::maps::CPointsMapXYZI& out, LoadReport& report);

}  // namespace tagmap::io
