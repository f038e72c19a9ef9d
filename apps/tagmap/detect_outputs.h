// The MRPT outputs of `tagmap detect` (docs/MRPT.md):
//   --landmarks F   CLandmarksMap, one beacon per tag (gz MRPT serialization)
//   --tagmap F      tagmap::maps::CTagMap with tags and points (needs the plugin to load)
//   --ini F         [MetricMap] block for pf-localization / ro-localization
//   --rawlog F      CObservation3DScene for a stock RawLogViewer, then the CTagMap
//   --3dscene F     COpenGLScene for SceneViewer3D
// Every file is written atomically.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>
#include <set>
#include <string>
#include <vector>

#include "cli.h"
#include "tagmap/detection_settings.h"
#include "tagmap/tag_detection.h"

namespace tagmap
{
struct Detections;
}

namespace tagmap::app
{
/** The value options above, for cli::parse(). */
const std::set<std::string>& mrptOutputOptions();

/** checkOutputWritable() for each requested output: call before detection, so
 *  an unwritable path fails at once instead of after minutes of work. */
void checkMrptOutputs(const cli::Args& args);

/** How the tags were detected, for the outputs that keep it: the CTagMap
 *  stores the resolved settings, the ini the user's choices. */
struct DetectionUsed
{
	DetectionChoices choices;
	PipelineParams params;
	std::vector<Eigen::Vector3d> viewpoints;  // where the sensors stood (local frame), if the input said
};

/** Writes every requested output (paths from `args`). `map` and the
 *  detections are in the local frame (file coordinates minus `origin`,
 *  io::LoadReport::origin), and so is every output: MRPT keeps points as
 *  float, and CLandmarksMap (also built from the ini) grids its landmarks
 *  from 0, which cannot reach UTM coordinates. The 3D scene and rawlog name
 *  the origin in the cloud's name. */
void writeMrptOutputs(const cli::Args& args, const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
					  const tagmap::Detections& found, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

/** Same, from the tags alone (tests, tools without a pipeline run). */
void writeMrptOutputs(const cli::Args& args, const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
					  const std::vector<TagDetection>& tags, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

}  // namespace tagmap::app
