// MRPT .simplemap input and the per-observation conversion shared with
// future rawlog readers.
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include "tagmap/io/mrpt_observations.h"
#include "test_io_helpers.h"

using namespace iotest;
using mrpt::poses::CPose3D;

namespace
{
const CPose3D kSensor(0.1, -0.2, 1.5, 0.3, 0.02, -0.01);
const CPose3D kKeyframes[2] = {CPose3D(0, 0, 0, 0, 0, 0), CPose3D(5.0, 2.0, 0.1, 1.2, 0.05, 0.0)};

mrpt::obs::CObservationPointCloud::Ptr xyziObservation(const std::vector<Pt>& pts)
{
	auto cloud = mrpt::maps::CPointsMapXYZI::Create();
	for (const auto& p : pts) cloud->insertPointRGB(p.x, p.y, p.z, p.i, 0, 0);
	auto obs = mrpt::obs::CObservationPointCloud::Create();
	obs->pointcloud = cloud;
	obs->sensorPose = kSensor;
	obs->sensorLabel = "lidar";
	return obs;
}

/** Two keyframes, each with an XYZI cloud and a 2D scan that must be skipped. */
mrpt::maps::CSimpleMap twoKeyframeMap(const std::vector<Pt>& local, std::vector<Pt>& expectedInMap)
{
	mrpt::maps::CSimpleMap sm;
	expectedInMap.clear();
	for (const CPose3D& kf : kKeyframes)
	{
		mrpt::obs::CSensoryFrame sf;
		sf.insert(xyziObservation(local));
		sf.insert(mrpt::obs::CObservation2DRangeScan::Create());
		sm.insert(mrpt::poses::CPose3DPDFGaussian(kf), sf);
		for (const auto& p : local)
		{
			const auto g = (kf + kSensor).composePoint(mrpt::math::TPoint3D(p.x, p.y, p.z));
			expectedInMap.push_back(Pt{static_cast<float>(g.x), static_cast<float>(g.y), static_cast<float>(g.z), p.i});
		}
	}
	return sm;
}
}  // namespace

TEST(IoSimplemap, MergesKeyframesAtPoseTimesSensorPose)
{
	const auto local = samplePoints(200);
	std::vector<Pt> expected;
	const auto sm = twoKeyframeMap(local, expected);
	const std::string path = scratchPath("two.simplemap");
	ASSERT_TRUE(sm.saveToFile(path));  // gzip-compressed
	tagmap::io::LoadReport r;
	const auto map = tagmap::io::loadPointCloud(path, &r);
	expectMapHolds(map, expected, 1e-4f);
	EXPECT_EQ(r.format, "simplemap");
	EXPECT_EQ(r.observationsUsed, 2u);
	EXPECT_EQ(r.observationsSkipped, 2u);
	EXPECT_EQ(r.pointsKept, 400u);
	// The second keyframe really moved the points: not just the first copied.
	float x, y, z;
	map.getPoint(200, x, y, z);
	EXPECT_GT(std::abs(x - expected[0].x) + std::abs(y - expected[0].y), 1.0f);
	// Where the sensor stood for each observation used (the 2D scans are
	// not): keyframe (+) sensor pose, in the file's frame and, less the
	// origin, in the map's.
	ASSERT_EQ(r.viewpoints.size(), 2u);
	const std::vector<Eigen::Vector3d> inMap = r.localViewpoints();
	for (size_t k = 0; k < 2; k++)
	{
		const CPose3D at = kKeyframes[k] + kSensor;
		EXPECT_NEAR((r.viewpoints[k] - Eigen::Vector3d(at.x(), at.y(), at.z())).norm(), 0, 1e-9);
		EXPECT_NEAR((inMap[k] + r.origin - r.viewpoints[k]).norm(), 0, 1e-9);
	}
}

TEST(IoSimplemap, ReadsUncompressedArchive)
{
	const auto local = samplePoints(50);
	std::vector<Pt> expected;
	const auto sm = twoKeyframeMap(local, expected);
	const std::string path = scratchPath("plain.simplemap");
	{
		mrpt::io::CFileOutputStream out(path);
		auto arch = mrpt::serialization::archiveFrom(out);
		arch << sm;
	}
	expectMapHolds(tagmap::io::loadPointCloud(path), expected, 1e-4f);
}

TEST(IoSimplemap, WithoutIntensityNamesWhatItFound)
{
	mrpt::maps::CSimpleMap sm;
	mrpt::obs::CSensoryFrame sf;
	auto obs = mrpt::obs::CObservationPointCloud::Create();
	auto xyz = mrpt::maps::CSimplePointsMap::Create();
	xyz->insertPoint(1, 2, 3);
	obs->pointcloud = xyz;
	sf.insert(obs);
	sf.insert(mrpt::obs::CObservation2DRangeScan::Create());
	sm.insert(mrpt::poses::CPose3DPDFGaussian(CPose3D()), sf);
	const std::string path = scratchPath("xyz.simplemap");
	ASSERT_TRUE(sm.saveToFile(path));
	expectInputError(path, "no observation with intensity in 1 keyframes (found: mrpt::obs::CObservation2DRangeScan x1, mrpt::obs::CObservationPointCloud x1)");
}

TEST(IoObservations, VelodynePointCloudIsPlacedAndKeepsIntensity)
{
	mrpt::obs::CObservationVelodyneScan velo;
	velo.sensorPose = kSensor;
	velo.point_cloud.x = {1.0f, 2.0f};
	velo.point_cloud.y = {0.5f, -1.0f};
	velo.point_cloud.z = {0.0f, 0.25f};
	velo.point_cloud.intensity = {17, 250};
	mrpt::maps::CPointsMapXYZI map;
	tagmap::io::LoadReport r;
	ASSERT_TRUE(tagmap::io::appendObservationToMap(velo, kKeyframes[1], map, r));
	std::vector<Pt> expected;
	for (size_t k = 0; k < 2; ++k)
	{
		const auto g = (kKeyframes[1] + kSensor).composePoint(mrpt::math::TPoint3D(velo.point_cloud.x[k], velo.point_cloud.y[k], velo.point_cloud.z[k]));
		expected.push_back(Pt{static_cast<float>(g.x), static_cast<float>(g.y), static_cast<float>(g.z), static_cast<float>(velo.point_cloud.intensity[k])});
	}
	expectMapHolds(map, expected, 1e-4f);
}

TEST(IoObservations, RangeScan3DUsesRobotAndSensorPose)
{
	mrpt::obs::CObservation3DRangeScan scan;
	scan.hasRangeImage = true;
	scan.rangeImage_setSize(3, 4);
	scan.rangeUnits = 0.001f;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) scan.rangeImage(r, c) = static_cast<uint16_t>(2000 + 100 * r + 10 * c);
	scan.cameraParams.ncols = 4;
	scan.cameraParams.nrows = 3;
	scan.cameraParams.fx(100);
	scan.cameraParams.fy(100);
	scan.cameraParams.cx(2);
	scan.cameraParams.cy(1.5);
	scan.cameraParamsIntensity = scan.cameraParams;
	scan.hasIntensityImage = true;
	scan.intensityImage = mrpt::img::CImage(4, 3, mrpt::img::CH_GRAY);
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) *scan.intensityImage(c, r) = static_cast<uint8_t>(20 * (r * 4 + c));

	mrpt::maps::CPointsMapXYZI atOrigin, placed;
	tagmap::io::LoadReport r;
	ASSERT_TRUE(tagmap::io::appendObservationToMap(scan, CPose3D(), atOrigin, r));
	ASSERT_EQ(atOrigin.size(), 12u);
	scan.sensorPose = kSensor;
	ASSERT_TRUE(tagmap::io::appendObservationToMap(scan, kKeyframes[1], placed, r));
	ASSERT_EQ(placed.size(), 12u);
	std::vector<Pt> expected;
	for (size_t k = 0; k < 12; ++k)
	{
		float x, y, z;
		atOrigin.getPoint(k, x, y, z);
		const auto g = (kKeyframes[1] + kSensor).composePoint(mrpt::math::TPoint3D(x, y, z));
		expected.push_back(Pt{static_cast<float>(g.x), static_cast<float>(g.y), static_cast<float>(g.z), atOrigin.getPointIntensity_fast(k)});
	}
	expectMapHolds(placed, expected, 1e-3f);
	for (size_t k = 0; k < 12; ++k) EXPECT_FLOAT_EQ(atOrigin.getPointIntensity_fast(k), 20.0f * static_cast<float>(k)) << k;

	scan.hasIntensityImage = false;
	mrpt::maps::CPointsMapXYZI none;
	EXPECT_FALSE(tagmap::io::appendObservationToMap(scan, CPose3D(), none, r));
	EXPECT_EQ(none.size(), 0u);
}
