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

/** Points the main viewport's camera at the tags: at their centroid, from
 *  the side they face, 20 deg above, far enough to see them all (without
 *  tags: the whole map). Viewers that honour the scene's camera
 *  (SceneViewer3D, with followCamera) start there. */
void aimCamera(mrpt::opengl::COpenGLScene& scene, const mrpt::maps::CPointsMapXYZI& map,
			   const std::vector<TagDetection>& tags);

/** The map, the tags and a camera aimed at them (aimCamera). */
mrpt::opengl::COpenGLScene::Ptr buildTagScene(const mrpt::maps::CPointsMapXYZI& map,
											  const std::vector<TagDetection>& tags,
											  const TagSceneParams& params = {});

/** buildTagScene() written atomically as a gz-compressed .3Dscene. */
void write3DScene(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
				  const std::vector<TagDetection>& tags, const TagSceneParams& params = {});

}  // namespace tagmap::mrpt_bridge
