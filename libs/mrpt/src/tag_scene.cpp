#include "tagmap/mrpt/tag_scene.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/opengl/CGridPlaneXY.h>

#include <cmath>

#include "tagmap/mrpt/serialize_gz.h"

namespace tagmap::mrpt_bridge
{
namespace
{
// The map's bounding box grown to include the tag centres; +-5 m around the
// origin for an empty map.
std::pair<mrpt::math::TPoint3D, mrpt::math::TPoint3D> sceneBounds(const mrpt::maps::CPointsMapXYZI& map,
																  const std::vector<TagDetection>& tags)
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
		hi.x = std::max(hi.x, c.x()), hi.y = std::max(hi.y, c.y()), hi.z = std::max(hi.z, c.z());
	}
	return {lo, hi};
}

mrpt::opengl::CGridPlaneXY::Ptr groundGrid(const mrpt::maps::CPointsMapXYZI& map, const std::vector<TagDetection>& tags)
{
	const auto [lo, hi] = sceneBounds(map, tags);
	// Whole metres, so grid lines fall on round coordinates.
	auto g = mrpt::opengl::CGridPlaneXY::Create(std::floor(lo.x), std::ceil(hi.x), std::floor(lo.y), std::ceil(hi.y),
												lo.z, 1.0);
	g->setColor_u8(120, 120, 120, 120);
	return g;
}
}  // namespace

void aimCamera(mrpt::opengl::COpenGLScene& scene, const mrpt::maps::CPointsMapXYZI& map,
			   const std::vector<TagDetection>& tags)
{
	auto& cam = scene.getViewport()->getCamera();
	if (tags.empty())
	{
		// Nothing to look at in particular: the whole map from above at 45 deg.
		const auto [lo, hi] = sceneBounds(map, tags);
		cam.setPointingAt(0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z));
		cam.setZoomDistance(static_cast<float>(std::max(5.0, 0.75 * (hi - lo).norm())));
		cam.setAzimuthDegrees(45);
		cam.setElevationDegrees(45);
		return;
	}
	// In front of the tags (they face where their z axes point, on average),
	// slightly from above: from behind, the wall a tag hangs on hides it.
	Eigen::Vector3d target = Eigen::Vector3d::Zero(), facing = Eigen::Vector3d::Zero();
	for (const auto& t : tags)
	{
		target += t.position() / static_cast<double>(tags.size());
		facing += t.pose.linear().col(2);
	}
	const double azimuth = std::hypot(facing.x(), facing.y()) > 0.2 * static_cast<double>(tags.size())
							   ? std::atan2(facing.y(), facing.x())
							   : mrpt::DEG2RAD(45.0);	// tags facing every way: any side will do
	const double elevation = mrpt::DEG2RAD(20.0);
	const Eigen::Vector3d toCamera(std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
								   std::sin(elevation));
	// Far enough that every tag fits across MRPT's default 30 deg field of view.
	double radius = 0;
	for (const auto& t : tags)
	{
		const Eigen::Vector3d d = t.position() - target;
		radius = std::max(radius, (d - d.dot(toCamera) * toCamera).norm() + t.size);
	}
	cam.setPointingAt(target.x(), target.y(), target.z());
	cam.setZoomDistance(static_cast<float>(std::max(3.0, 1.3 * radius / std::tan(mrpt::DEG2RAD(15.0)))));
	cam.setAzimuthDegrees(static_cast<float>(mrpt::RAD2DEG(azimuth)));
	cam.setElevationDegrees(static_cast<float>(mrpt::RAD2DEG(elevation)));
}

mrpt::opengl::COpenGLScene::Ptr buildTagScene(const mrpt::maps::CPointsMapXYZI& map,
											  const std::vector<TagDetection>& tags, const TagSceneParams& params)
{
	auto scene = mrpt::opengl::COpenGLScene::Create();
	if (params.showGrid) scene->insert(groundGrid(map, tags));
	if (params.showPoints && !map.empty()) scene->insert(makeIntensityCloud(map, params.cloud, tags));
	for (const auto& t : tags) scene->insert(makeTagVisual(t, params.tag));
	aimCamera(*scene, map, tags);
	// SceneViewer3D starts from the scene's own camera only when asked to;
	// otherwise at 20 m from the origin, which for a site map is anywhere.
	scene->enableFollowCamera(true);
	return scene;
}

void write3DScene(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
				  const std::vector<TagDetection>& tags, const TagSceneParams& params)
{
	writeSerializableGz(path, *buildTagScene(map, tags, params));
}

}  // namespace tagmap::mrpt_bridge
