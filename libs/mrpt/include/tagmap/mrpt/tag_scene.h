// A whole result as an MRPT 3D scene: the map coloured by intensity plus every
// tag drawn with its real pattern. Written as a .3Dscene for SceneViewer3D and
// embedded in the rawlog's CObservation3DScene for RawLogViewer.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <string>
#include <vector>

#include "tagmap/mrpt/intensity_cloud.h"
#include "tagmap/mrpt/tag_visual.h"

namespace tagmap::mrpt_bridge
{
struct TagSceneParams
{
	bool showGrid = true;  // a ground grid gives scale when the map is sparse
	bool showPoints = true;
	IntensityCloudParams cloud;
	TagVisualParams tag;
};

mrpt::opengl::COpenGLScene::Ptr buildTagScene(const mrpt::maps::CPointsMapXYZI& map,
											  const std::vector<TagDetection>& tags,
											  const TagSceneParams& params = {});

/** buildTagScene() written atomically as a gz-compressed .3Dscene. */
void write3DScene(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
				  const std::vector<TagDetection>& tags, const TagSceneParams& params = {});

}  // namespace tagmap::mrpt_bridge
