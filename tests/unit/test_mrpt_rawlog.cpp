// .rawlog input: LiDAR observations merged at the rawlog's odometry poses,
// or at a TUM trajectory's poses when the rawlog has none.
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>

#include <fstream>

#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/mrpt/serialize_gz.h"

namespace
{
mrpt::obs::CObservationPointCloud::Ptr onePointScan(double t)
{
	auto pc = mrpt::maps::CPointsMapXYZI::Create();
	pc->insertPoint(1, 0, 0);
	pc->setPointIntensity(0, 0.5f);
	auto obs = mrpt::obs::CObservationPointCloud::Create();
	obs->pointcloud = pc;
	obs->timestamp = mrpt::Clock::fromDouble(t);
	return obs;
}

std::string dir() { return std::string(TAGMAP_BINARY_DIR) + "/"; }
}  // namespace

TEST(MrptRawlogInput, OdometryPoses)
{
	std::vector<mrpt::serialization::CSerializable::Ptr> objs;
	for (int k = 0; k < 2; k++)
	{
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->odometry = mrpt::poses::CPose2D(10.0 * k, 0, k * M_PI / 2);
		objs.push_back(odo);
		objs.push_back(onePointScan(k));
	}
	const std::string path = dir() + "test_mrpt_odo.rawlog";
	tagmap::mrpt_bridge::writeSerializableSequenceGz(path, objs);
	tagmap::io::LoadReport report;
	const auto map = tagmap::io::loadPointCloud(path, &report);
	ASSERT_EQ(map.size(), 2u);
	EXPECT_EQ(report.format, "rawlog");
	EXPECT_NEAR(map.getPointsBufferRef_x()[1], 10.0, 1e-5);
	EXPECT_NEAR(map.getPointsBufferRef_y()[1], 1.0, 1e-5);  // rotated 90 degrees
}

TEST(MrptRawlogInput, TumPosesWhenNoOdometry)
{
	const std::string path = dir() + "test_mrpt_tum.rawlog";
	tagmap::mrpt_bridge::writeSerializableSequenceGz(path, {onePointScan(100.0), onePointScan(101.0)});
	std::ofstream(dir() + "test_mrpt_tum.tum") << "# t x y z qx qy qz qw\n100 0 0 0 0 0 0 1\n101 0 5 0 0 0 0 1\n";
	const auto map = tagmap::io::loadPointCloud(path);
	ASSERT_EQ(map.size(), 2u);
	EXPECT_NEAR(map.getPointsBufferRef_y()[1], 5.0, 1e-5);
}

TEST(MrptRawlogInput, NoPosesIsAnError)
{
	const std::string path = dir() + "test_mrpt_noposes.rawlog";
	tagmap::mrpt_bridge::writeSerializableSequenceGz(path, {onePointScan(1), onePointScan(2)});
	EXPECT_THROW(tagmap::io::loadPointCloud(path), tagmap::InputError);
}
