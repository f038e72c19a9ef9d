// A LiDAR map for MRPT's viewers, coloured by intensity: tags are found in
// the intensity channel, so that is the channel worth seeing.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>
#include <mrpt/opengl/CPointCloudColoured.h>

namespace tagmap::mrpt_bridge
{
struct IntensityCloudParams
{
	float pointSize = 2.0f;
	size_t maxPoints = 2000000;  // decimate beyond this to keep viewers responsive
};

/** Points in map coordinates; intensity mapped to a jet colour map over the
 *  map's own [1st, 99th] percentile range, so a few retro-reflective outliers
 *  do not wash out everything else. */
mrpt::opengl::CPointCloudColoured::Ptr makeIntensityCloud(const mrpt::maps::CPointsMapXYZI& map,
														   const IntensityCloudParams& params = {});

}  // namespace tagmap::mrpt_bridge
