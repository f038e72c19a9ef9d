// A result as an observations-only .rawlog with one entry, a
// CObservation3DScene (map coloured by intensity + tags with their bitmaps),
// which a stock RawLogViewer shows without any plugin. Nothing of the plugin
// goes in: MRPT cannot skip an object of an unregistered class, so a stock
// reader would log an error on it (see docs/MRPT.md for where CTagMap goes).
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <string>
#include <vector>

#include "tagmap/mrpt/tag_scene.h"

namespace tagmap::mrpt_bridge
{
struct RawlogParams
{
	std::string sensorLabel = "tagmap";
	TagSceneParams scene;
};

void writeTagRawlog(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
					const std::vector<TagDetection>& tags, const RawlogParams& params = {});

}  // namespace tagmap::mrpt_bridge
