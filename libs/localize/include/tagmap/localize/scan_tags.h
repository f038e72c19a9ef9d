// Tags in one LiDAR scan, relative to the sensor: the mapping pipeline
// (tagmap::Pipeline) run on a single scan expressed in the sensor frame, so
// {G} is the sensor frame and every detection's pose is T_sensor_tag with
// its 6x6 covariance in that frame.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/obs/CObservation.h>

#include <optional>
#include <vector>

#include "tagmap/pipeline.h"
#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
/** Pipeline parameters for scans detected `window` at a time (observe's
 *  --window). One scan has one viewpoint, so its candidates come from its
 *  own sensor view (sensor_view.h: the fast path, and on sparse spinning
 *  scans it sees more tags); scans merged over a window are seen from
 *  several places while the robot moves, and take the map path. */
PipelineParams singleScanPipelineParams(size_t window = 1);

/** The scan's points in its own sensor frame (the observation's sensorPose
 *  undone), or nullopt for observations without intensity (not LiDAR). */
std::optional<mrpt::maps::CPointsMapXYZI> scanInSensorFrame(const mrpt::obs::CObservation& obs);

/** Every tag the pipeline finds in `scan` (sensor frame): poses T_sensor_tag. */
std::vector<TagDetection> detectTagsInScan(const Pipeline& pipeline, const mrpt::maps::CPointsMapXYZI& scan);

}  // namespace tagmap::localize
