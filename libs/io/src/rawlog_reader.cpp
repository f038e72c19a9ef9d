// MRPT .rawlog of LiDAR observations with intensity, merged into one map.
// Where each observation was taken from, in order of preference:
//   1. the rawlog itself: odometry (CObservationOdometry in observations-only
//      rawlogs, CActionCollection increments in action/sensory-frame ones);
//   2. a TUM trajectory next to it (X.rawlog -> X.tum: "t x y z qx qy qz qw"
//      per line), interpolated at each observation's timestamp.
// A rawlog with several observations and neither is rejected: stacking scans
// at the origin would make a map that silently is not one.
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/poses/CPose3DInterpolator.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "readers.h"
#include "tagmap/errors.h"
#include "tagmap/io/mrpt_observations.h"
#include "tagmap/io/rawlog_file.h"

namespace tagmap::io::detail
{
namespace
{
struct PosedObservation
{
	mrpt::obs::CObservation::Ptr obs;
	std::optional<mrpt::poses::CPose3D> pose;  // from the rawlog's own odometry
};

/** Walks the rawlog in order, integrating its odometry as it goes. */
std::vector<PosedObservation> observationsWithOdometry(const mrpt::obs::CRawlog& log)
{
	std::vector<PosedObservation> out;
	std::optional<mrpt::poses::CPose3D> pose;
	for (size_t i = 0; i < log.size(); i++)
	{
		switch (log.getType(i))
		{
			case mrpt::obs::CRawlog::etActionCollection:
			{
				mrpt::poses::CPose3D increment;
				if (log.getAsAction(i)->getFirstMovementEstimationMean(increment))
					pose = pose.value_or(mrpt::poses::CPose3D()) + increment;
				break;
			}
			case mrpt::obs::CRawlog::etSensoryFrame:
				for (const auto& o : *log.getAsObservations(i)) out.push_back({o, pose});
				break;
			case mrpt::obs::CRawlog::etObservation:
			{
				auto o = log.getAsObservation(i);
				if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o))
					pose = mrpt::poses::CPose3D(odo->odometry);
				else
					out.push_back({o, pose});
				break;
			}
			default: break;
		}
	}
	return out;
}

std::optional<mrpt::poses::CPose3DInterpolator> readTum(const std::string& rawlogPath)
{
	const auto tum = std::filesystem::path(rawlogPath).replace_extension(".tum").string();
	std::ifstream in(tum);
	if (!in) return std::nullopt;
	mrpt::poses::CPose3DInterpolator path;
	std::string line;
	for (size_t n = 1; std::getline(in, line); n++)
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream is(line);
		double t, x, y, z, qx, qy, qz, qw;
		if (!(is >> t >> x >> y >> z >> qx >> qy >> qz >> qw))
			throw InputError(tum, "line " + std::to_string(n), "expected 't x y z qx qy qz qw'");
		const mrpt::math::CQuaternionDouble q(qw, qx, qy, qz);
		path.insert(mrpt::Clock::fromDouble(t), mrpt::poses::CPose3D(q, x, y, z).asTPose());
	}
	return path;
}
}  // namespace

void readRawlog(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const mrpt::obs::CRawlog log = loadRawlog(path);
	report.format = "rawlog";
	report.intensityField = "observation intensity";

	const auto observations = observationsWithOdometry(log);
	const bool haveOdometry = std::any_of(observations.begin(), observations.end(), [](auto& p) { return p.pose; });
	const auto tum = haveOdometry ? std::nullopt : readTum(path);
	if (!haveOdometry && !tum && observations.size() > 1)
		throw InputError(path, "", "no poses: the rawlog has no odometry and there is no TUM trajectory " +
									   std::filesystem::path(path).replace_extension(".tum").string());

	for (const auto& [obs, odoPose] : observations)
	{
		mrpt::poses::CPose3D pose = odoPose.value_or(mrpt::poses::CPose3D());
		if (tum)
		{
			bool valid = false;
			tum->interpolate(obs->timestamp, pose, valid);
			if (!valid)
			{
				++report.observationsSkipped;  // outside the trajectory's time span
				continue;
			}
		}
		appendObservationToMap(*obs, pose, out, report);  // counts used / skipped itself
	}
	if (report.observationsUsed == 0)
		throw InputError(path, "",
						 "no observation with intensity; expected CObservationPointCloud with a CPointsMapXYZI, "
						 "CObservationVelodyneScan or CObservation3DRangeScan with intensity");
}

}  // namespace tagmap::io::detail
