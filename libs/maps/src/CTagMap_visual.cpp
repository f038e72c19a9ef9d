// CTagMap in MRPT viewers: the same tag visuals as tagmap's .3Dscene and
// rawlog outputs (tagmap/mrpt/tag_visual.h), so a map looks identical
// whichever way it reaches the user.
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/intensity_cloud.h"
#include "tagmap/mrpt/tag_visual.h"

namespace tagmap::maps
{
void CTagMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const
{
	if (!genericMapParams.enableSaveAs3DObject) return;

	if (visualOptions.showPoints && !m_points.empty())
	{
		mrpt_bridge::IntensityCloudParams cp;
		cp.pointSize = static_cast<float>(visualOptions.pointSize);
		o.insert(mrpt_bridge::makeIntensityCloud(m_points, cp, tags()));
	}
	mrpt_bridge::TagVisualParams vp;
	vp.showLabel = visualOptions.showLabels;
	vp.showAxes = visualOptions.showAxes;
	for (const auto& t : tags()) o.insert(mrpt_bridge::makeTagVisual(t, vp));
}

}  // namespace tagmap::maps
