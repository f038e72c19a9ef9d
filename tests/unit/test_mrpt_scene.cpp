// The 3D outputs as MRPT's viewers start them: SceneViewer3D's first view is
// aimed at the tags, no points show through a tag's pattern, and the
// --rawlog holds nothing a stock MRPT cannot read.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation3DScene.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

#include "../mrpt/synthetic_tags.h"
#include "tagmap/mrpt/intensity_cloud.h"
#include "tagmap/mrpt/rawlog_writer.h"
#include "tagmap/mrpt/tag_scene.h"

using namespace tagmap;

namespace
{
const std::string kDir = TAGMAP_BINARY_DIR;
}

TEST(MrptScene, CameraInFrontOfTheTagsSurvivesTheFile)
{
	const auto tags = mrpt_test::syntheticTags();
	const std::string path = kDir + "/test_mrpt_scene.3Dscene";
	mrpt_bridge::write3DScene(path, mrpt_test::syntheticWallMap(tags), tags);

	mrpt::opengl::COpenGLScene scene;
	mrpt::io::CFileGZInputStream f(path);
	mrpt::serialization::archiveFrom(f) >> scene;
	EXPECT_TRUE(scene.followCamera());	// else SceneViewer3D ignores the camera
	const auto& cam = scene.getViewport()->getCamera();

	Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
	for (const auto& t : tags) centroid += t.position() / static_cast<double>(tags.size());
	EXPECT_NEAR(cam.getPointingAtX(), centroid.x(), 1e-4);
	EXPECT_NEAR(cam.getPointingAtY(), centroid.y(), 1e-4);
	EXPECT_NEAR(cam.getPointingAtZ(), centroid.z(), 1e-4);
	// The synthetic tags face -x: the camera must be on that side, not behind the wall.
	EXPECT_NEAR(std::abs(cam.getAzimuthDegrees()), 180.0, 1e-3);
	EXPECT_GT(cam.getElevationDegrees(), 0);
	EXPECT_LT(cam.getElevationDegrees(), 45);
	// Every tag within the default 30 deg field of view (half-angle 15 deg).
	const double az = mrpt::DEG2RAD(cam.getAzimuthDegrees()), el = mrpt::DEG2RAD(cam.getElevationDegrees());
	const Eigen::Vector3d eye =
		centroid + cam.getZoomDistance() * Eigen::Vector3d(std::cos(az) * std::cos(el), std::sin(az) * std::cos(el),
														   std::sin(el));
	for (const auto& t : tags)
	{
		const Eigen::Vector3d toTag = (t.position() - eye).normalized(), toTarget = (centroid - eye).normalized();
		EXPECT_LT(std::acos(toTag.dot(toTarget)), mrpt::DEG2RAD(15.0)) << t.family << ":" << t.id;
	}
}

TEST(MrptScene, EmptyResultLooksAtTheMap)
{
	mrpt::maps::CPointsMapXYZI map;
	map.insertPointFast(10, 20, 0);
	map.insertPointFast(14, 24, 2);
	const auto scene = mrpt_bridge::buildTagScene(map, {});
	const auto& cam = scene->getViewport()->getCamera();
	EXPECT_NEAR(cam.getPointingAtX(), 12, 1e-4);
	EXPECT_NEAR(cam.getPointingAtY(), 22, 1e-4);
	EXPECT_NEAR(cam.getPointingAtZ(), 1, 1e-4);
}

TEST(MrptScene, RawlogIsTheSceneOnly)
{
	const auto tags = mrpt_test::syntheticTags();
	const std::string path = kDir + "/test_mrpt_scene.rawlog";
	mrpt_bridge::writeTagRawlog(path, mrpt_test::syntheticWallMap(tags), tags);
	mrpt::obs::CRawlog rawlog;
	ASSERT_TRUE(rawlog.loadFromRawLogFile(path));
	ASSERT_EQ(rawlog.size(), 1u);
	const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation3DScene>(rawlog.getAsGeneric(0));
	ASSERT_TRUE(obs);
	ASSERT_TRUE(obs->scene);
	// grid + points + one visual per tag
	EXPECT_EQ(obs->scene->getViewport()->size(), 2 + tags.size());
}

TEST(MrptScene, PointsUnderAPatternLeftOut)
{
	const auto tags = mrpt_test::syntheticTags();
	const auto map = mrpt_test::syntheticWallMap(tags);
	const auto cloud = mrpt_bridge::makeIntensityCloud(map, {}, tags);
	EXPECT_LT(cloud->size(), map.size());
	EXPECT_GT(cloud->size(), map.size() * 8 / 10);	// the wall around the tags stays
	for (size_t i = 0; i < cloud->size(); i++)
	{
		const auto& p = cloud->getPoint3Df(i);
		for (const auto& t : tags)
		{
			const Eigen::Vector3d q = t.pose.inverse() * Eigen::Vector3d(p.x, p.y, p.z);
			const double h = mrpt_bridge::drawnHalfSide(t) - 1e-3;
			ASSERT_FALSE(std::abs(q.x()) < h && std::abs(q.y()) < h) << t.family << ":" << t.id;
		}
	}
	EXPECT_EQ(mrpt_bridge::makeIntensityCloud(map)->size(), map.size());
}
