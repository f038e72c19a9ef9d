#include "tagmap/mrpt/tag_scene.h"

#include <mrpt/opengl/CGridPlaneXY.h>

#include <cmath>

#include "tagmap/mrpt/serialize_gz.h"

namespace tagmap::mrpt_bridge
{
namespace
{
mrpt::opengl::CGridPlaneXY::Ptr groundGrid(const mrpt::maps::CPointsMapXYZI& map, const std::vector<TagDetection>& tags)
{
	mrpt::math::TPoint3D lo(-5, -5, 0), hi(5, 5, 0);
	if (!map.empty())
	{
		const auto bb = map.boundingBox();
		lo = {bb.min.x, bb.min.y, bb.min.z}, hi = {bb.max.x, bb.max.y, bb.max.z};
	}
	for (const auto& t : tags)
	{
		const auto c = t.position();
		lo.x = std::min(lo.x, c.x()), lo.y = std::min(lo.y, c.y()), lo.z = std::min(lo.z, c.z());
		hi.x = std::max(hi.x, c.x()), hi.y = std::max(hi.y, c.y());
	}
	// Whole metres, so grid lines fall on round coordinates.
	auto g = mrpt::opengl::CGridPlaneXY::Create(std::floor(lo.x), std::ceil(hi.x), std::floor(lo.y), std::ceil(hi.y),
												lo.z, 1.0);
	g->setColor_u8(120, 120, 120, 120);
	return g;
}
}  // namespace

mrpt::opengl::COpenGLScene::Ptr buildTagScene(const mrpt::maps::CPointsMapXYZI& map,
											  const std::vector<TagDetection>& tags, const TagSceneParams& params)
{
	auto scene = mrpt::opengl::COpenGLScene::Create();
	if (params.showGrid) scene->insert(groundGrid(map, tags));
	if (params.showPoints && !map.empty()) scene->insert(makeIntensityCloud(map, params.cloud));
	for (const auto& t : tags) scene->insert(makeTagVisual(t, params.tag));
	return scene;
}

void write3DScene(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
				  const std::vector<TagDetection>& tags, const TagSceneParams& params)
{
	writeSerializableGz(path, *buildTagScene(map, tags, params));
}

}  // namespace tagmap::mrpt_bridge
