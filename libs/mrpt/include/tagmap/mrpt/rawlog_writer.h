// A result as an observations-only .rawlog. The first entry is a
// CObservation3DScene (map coloured by intensity + tags with their
// bitmaps), which a stock RawLogViewer shows without any plugin. Further
// objects (e.g. a tagmap::maps::CTagMap for users who load the plugin) go
// after it, so a reader that cannot parse them still gets the scene first.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/serialization/CSerializable.h>

#include <string>
#include <vector>

#include "tagmap/mrpt/tag_scene.h"

namespace tagmap::mrpt_bridge
{
struct RawlogParams
{
	std::string sensorLabel = "tagmap";
	TagSceneParams scene;
	std::vector<mrpt::serialization::CSerializable::Ptr> extraObjects;
};

void writeTagRawlog(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
					const std::vector<TagDetection>& tags, const RawlogParams& params = {});

}  // namespace tagmap::mrpt_bridge
