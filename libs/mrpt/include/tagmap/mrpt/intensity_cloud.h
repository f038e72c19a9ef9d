// A LiDAR map for MRPT's viewers, coloured by intensity: tags are found in
// the intensity channel, so that is the channel worth seeing.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/opengl/CPointCloudColoured.h>

#include <Eigen/Core>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_bridge
{
struct IntensityCloudParams
{
	float pointSize = 2.0f;
	size_t maxPoints = 2000000;  // decimate beyond this to keep viewers responsive
	/** The map's local origin (io::LoadReport::origin): MRPT stores the
	 *  cloud's points as float, so they stay in the local frame and a
	 *  non-zero origin is written in the cloud's name, "map (local frame:
	 *  file = local + (x, y, z) m)", for the viewer's object list. */
	Eigen::Vector3d localOrigin = Eigen::Vector3d::Zero();
};

/** Points in map coordinates; intensity mapped to a jet colour map over the
 *  map's own [1st, 99th] percentile range, so a few retro-reflective outliers
 *  do not wash out everything else.
 *  Points under the pattern of a tag in `drawnOver` (within its drawn square,
 *  drawnHalfSide(), and 10 cm of its plane) are left out: the pattern stands
 *  for them, and a viewer with a 16-bit depth buffer (MRPT's GL canvases
 *  under Xvfb, some drivers) cannot keep points a few cm behind a textured
 *  square from showing through it. */
mrpt::opengl::CPointCloudColoured::Ptr makeIntensityCloud(const mrpt::maps::CPointsMapXYZI& map,
														   const IntensityCloudParams& params = {},
														   const std::vector<TagDetection>& drawnOver = {});

}  // namespace tagmap::mrpt_bridge
