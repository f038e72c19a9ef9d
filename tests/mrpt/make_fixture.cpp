// Inputs of the MRPT tool tests (tests/mrpt/*.sh).
//   tagmap_mrpt_fixture DIR
//     DIR/map.landmarks.gz map.tagmap map.ini map.rawlog map.3Dscene through the
//     same writeMrptOutputs() as `tagmap detect`, on synthetic tags;
//     DIR/beacons.rawlog: a robot driving past the wall, observing ranges to
//     the tags as beacons, for pf-localization with map.ini.
//   tagmap_mrpt_fixture --beacons TRUTH.tum TAGS.json OUT.rawlog [EVERY]
//     the same kind of beacons rawlog along a simulated trajectory (every
//     EVERY-th pose), ranges to the tags of a ground-truth file. A robot with
//     a real tag detector in every scan would record this; `tagmap observe`
//     cannot yet on 0.1 s Livox frames (docs/LOCALIZATION.md).
// A beacons rawlog is obs-only: CObservationOdometry (perfect, the tests are
// about the map) + CObservationBeaconRanges (2 cm noise).
#include <mrpt/obs/CObservationBeaconRanges.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/random/RandomGenerators.h>
#include <filesystem>

#include <iostream>
#include <stdexcept>

#include "../../apps/tagmap/detect_outputs.h"
#include "synthetic_tags.h"
#include "tagmap/localize/trajectory_tum.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/serialize_gz.h"
#include "tagmap/tags_json.h"

namespace
{
// The robot frame is the sensor's pose on the ground plane; the sensor sits
// at its height above it, so ranges are true 3D distances.
void writeBeaconRawlog(const std::string& path, const tagmap::localize::Trajectory& truth,
					   const std::vector<tagmap::TagDetection>& tags)
{
	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(1234);  // reproducible test input
	std::vector<mrpt::serialization::CSerializable::Ptr> objs;
	for (const auto& [stamp, pose] : truth)
	{
		const Eigen::Vector3d p = pose.translation(), heading = pose.linear().col(0);
		const auto t = mrpt::Clock::fromDouble(stamp);
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->odometry = mrpt::poses::CPose2D(p.x(), p.y(), std::atan2(heading.y(), heading.x()));
		odo->timestamp = t;
		odo->sensorLabel = "ODOMETRY";
		objs.push_back(odo);

		auto obs = mrpt::obs::CObservationBeaconRanges::Create();
		obs->timestamp = t;
		obs->sensorLabel = "BEACONS";
		obs->minSensorDistance = 0;
		obs->maxSensorDistance = 60;
		obs->stdError = 0.02f;
		for (const auto& tag : tags)
		{
			mrpt::obs::CObservationBeaconRanges::TMeasurement m;
			m.beaconID = static_cast<int32_t>(tagmap::mrpt_bridge::encodeBeaconId(tag.family, tag.id));
			m.sensorLocationOnRobot = mrpt::poses::CPoint3D(0, 0, p.z());
			m.sensedDistance = static_cast<float>((tag.position() - p).norm() + rng.drawGaussian1D(0, 0.02));
			obs->sensedData.push_back(m);
		}
		objs.push_back(obs);
	}
	tagmap::mrpt_bridge::writeSerializableSequenceGz(path, objs);
}

// The synthetic robot of the fixture: past the wall, ending at x=3.4, y=0.45
// (tests/mrpt/pf_localization.sh checks the filter gets there).
tagmap::localize::Trajectory fixtureTrajectory()
{
	tagmap::localize::Trajectory truth;
	for (int k = 0; k < 30; k++)
	{
		tagmap::localize::StampedPose s;
		s.stamp = 1.7e9 + 0.1 * k;
		s.pose.translation() = Eigen::Vector3d(0.5 + 0.1 * k, -1.0 + 0.05 * k, 0);
		s.pose.linear() = Eigen::AngleAxisd(0.05 * k, Eigen::Vector3d::UnitZ()).toRotationMatrix();
		truth.push_back(s);
	}
	return truth;
}

int writeBeaconsAlong(int argc, char** argv)
{
	auto truth = tagmap::localize::readTum(argv[2]);
	const auto tags = tagmap::readTagsJson(argv[3]);
	size_t every = 1;
	if (argc == 6)
	{
		const std::string e = argv[5];
		if (e.empty() || e.find_first_not_of("0123456789") != std::string::npos || (every = std::stoul(e)) == 0)
			throw std::runtime_error("EVERY must be a positive integer, not '" + e + "'");
	}
	tagmap::localize::Trajectory kept;
	for (size_t i = 0; i < truth.size(); i += every) kept.push_back(truth[i]);
	if (kept.empty()) throw std::runtime_error(std::string(argv[2]) + ": no poses");
	writeBeaconRawlog(argv[4], kept, tags);
	const Eigen::Vector3d end = kept.back().pose.translation();
	// The last line is what tests/mrpt/pf_localization.sh compares the filter's end with.
	std::cout << "beacons: " << kept.size() << " poses, " << tags.size() << " tags -> " << argv[4] << "\n"
			  << "end " << end.x() << " " << end.y() << "\n";
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc >= 5 && argc <= 6 && std::string(argv[1]) == "--beacons") try
		{
			return writeBeaconsAlong(argc, argv);
		}
		catch (const std::exception& e)
		{
			std::cerr << "tagmap_mrpt_fixture: " << e.what() << "\n";
			return 1;
		}
	if (argc != 2)
	{
		std::cerr << "usage: tagmap_mrpt_fixture OUTDIR | --beacons TRUTH.tum TAGS.json OUT.rawlog [EVERY]\n";
		return 2;
	}
	const std::string dir = argv[1];
	std::filesystem::create_directories(dir);
	const auto tags = tagmap::mrpt_test::syntheticTags();
	const auto map = tagmap::mrpt_test::syntheticWallMap(tags);

	tagmap::cli::Args args;
	args.options = {{"--landmarks", dir + "/map.landmarks.gz"}, {"--tagmap", dir + "/map.tagmap"},
					{"--ini", dir + "/map.ini"},				{"--rawlog", dir + "/map.rawlog"},
					{"--3dscene", dir + "/map.3Dscene"}};
	tagmap::app::DetectionUsed used;
	used.choices.families = "tag36h11,aruco_4x4_50";
	used.params = tagmap::resolveDetectionSettings(used.choices);
	tagmap::app::checkMrptOutputs(args);
	tagmap::app::writeMrptOutputs(args, used, map, tags);
	writeBeaconRawlog(dir + "/beacons.rawlog", fixtureTrajectory(), tags);
	std::cout << "fixture: " << tags.size() << " tags, " << map.size() << " points in " << dir << "\n";
	return 0;
}
