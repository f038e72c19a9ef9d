// Writes the inputs of the MRPT tool tests (tests/mrpt/*.sh) into one folder:
//   map.landmarks.gz map.tagmap map.ini map.rawlog map.3Dscene
//     - through the same writeMrptOutputs() as `tagmap detect`, on synthetic tags;
//   beacons.rawlog
//     - a robot driving past the wall, observing ranges to the tags as beacons
//       (obs-only rawlog: CObservationOdometry + CObservationBeaconRanges),
//       for pf-localization with map.ini.
#include <mrpt/obs/CObservationBeaconRanges.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/random/RandomGenerators.h>
#include <filesystem>

#include <iostream>

#include "../../apps/tagmap/detect_outputs.h"
#include "synthetic_tags.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/serialize_gz.h"

namespace
{
void writeBeaconRawlog(const std::string& path, const std::vector<tagmap::TagDetection>& tags)
{
	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(1234);  // reproducible test input
	std::vector<mrpt::serialization::CSerializable::Ptr> objs;
	auto t = mrpt::Clock::fromDouble(1.7e9);
	for (int k = 0; k < 30; k++)
	{
		const mrpt::poses::CPose2D truth(0.5 + 0.1 * k, -1.0 + 0.05 * k, 0.05 * k);
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->odometry = truth;  // perfect odometry: the test is about the map
		odo->timestamp = t;
		odo->sensorLabel = "ODOMETRY";
		objs.push_back(odo);

		auto obs = mrpt::obs::CObservationBeaconRanges::Create();
		obs->timestamp = t;
		obs->sensorLabel = "BEACONS";
		obs->minSensorDistance = 0;
		obs->maxSensorDistance = 30;
		obs->stdError = 0.02f;
		for (const auto& tag : tags)
		{
			const Eigen::Vector3d c = tag.position();
			mrpt::obs::CObservationBeaconRanges::TMeasurement m;
			m.beaconID = static_cast<int32_t>(tagmap::mrpt_bridge::encodeBeaconId(tag.family, tag.id));
			m.sensorLocationOnRobot = mrpt::poses::CPoint3D(0, 0, 0);
			const double range = mrpt::poses::CPoint3D(truth.x(), truth.y(), 0).distanceTo(
				mrpt::poses::CPoint3D(c.x(), c.y(), c.z()));
			m.sensedDistance = static_cast<float>(range + rng.drawGaussian1D(0, 0.02));
			obs->sensedData.push_back(m);
		}
		objs.push_back(obs);
		t += std::chrono::milliseconds(100);
	}
	tagmap::mrpt_bridge::writeSerializableSequenceGz(path, objs);
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::cerr << "usage: tagmap_mrpt_fixture OUTDIR\n";
		return 2;
	}
	const std::string dir = argv[1];
	std::filesystem::create_directories(dir);
	const auto tags = tagmap::mrpt_test::syntheticTags();
	const auto map = tagmap::mrpt_test::syntheticWallMap(tags);

	tagmap::cli::Args args;
	args.options = {{"--landmarks", dir + "/map.landmarks.gz"}, {"--tagmap", dir + "/map.tagmap"},
					{"--ini", dir + "/map.ini"},				{"--rawlog", dir + "/map.rawlog"},
					{"--3dscene", dir + "/map.3Dscene"},		{"--family", "tag36h11,aruco_4x4_50"}};
	tagmap::app::checkMrptOutputs(args);
	tagmap::app::writeMrptOutputs(args, map, tags);
	writeBeaconRawlog(dir + "/beacons.rawlog", tags);
	std::cout << "fixture: " << tags.size() << " tags, " << map.size() << " points in " << dir << "\n";
	return 0;
}
