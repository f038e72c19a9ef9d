// The `--ini` output: a [MetricMap] block (mrpt::maps::CMultiMetricMap /
// TSetOfMetricMapInitializers format) that stock MRPT apps such as
// pf-localization and ro-localization load as-is. The tags become a
// CLandmarksMap of beacons ("landmarksMap" with nBeacons / beacon_%03u_ID,x,y,z
// keys, MRPT 2.5's CLandmarksMap::TMapDefinition), keyed by beacon_id.h.
// A second map "tagMap" carries the full tags for the tagmap plugin and scores
// the tag poses (CObservationTagPoses; the landmarksMap scores the ranges);
// stock MRPT skips it because no class registers that name until the plugin
// loads (docs/MRPT.md, "pf-localization with the tag poses").
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_bridge
{
struct MetricMapIniParams
{
	std::string sectionName = "MetricMap";  // the apps read "[MetricMap]"
	double beaconRangesStd = 0.08;  // metres; CLandmarksMap's default
	bool includeTagMap = true;
	/** The tagMap's tagPoseExtraStd* (metres, degrees): a stock particle
	 *  filter updates once per scan from a uniform start, so the tag-pose
	 *  model must be wide enough for its nearest particles (tagmap localize
	 *  anneals instead). Measured with stock pf-localization on the quick
	 *  localize demo: docs/MRPT.md. */
	double tagPoseExtraStdPosition = 0.1;
	double tagPoseExtraStdRotationDeg = 2;
	/** Extra keys for the tagMap's "_detectionOpts" section (the plugin's
	 *  detection parameters), written verbatim as key=value. */
	std::vector<std::pair<std::string, std::string>> tagMapDetectionOptions;
};

std::string metricMapIni(const std::vector<TagDetection>& tags, const MetricMapIniParams& params = {});

/** metricMapIni() written atomically. */
void writeMetricMapIni(const std::string& path, const std::vector<TagDetection>& tags,
					   const MetricMapIniParams& params = {});

}  // namespace tagmap::mrpt_bridge
