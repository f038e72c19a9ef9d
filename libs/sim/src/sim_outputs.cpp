#include "tagmap/sim/sim_outputs.h"

#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <cstdio>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/local_frame.h"
#include "tagmap/tags_json.h"

namespace tagmap::sim
{
namespace
{
mrpt::poses::CPose3D toMrpt(const Eigen::Isometry3d& T)
{
	mrpt::math::CMatrixDouble44 M;
	for (int r = 0; r < 4; r++)
		for (int c = 0; c < 4; c++) M(r, c) = T.matrix()(r, c);
	return mrpt::poses::CPose3D(M);
}

/** Each truth tag's sighting conditions as JSON members (the names the
 *  ground truth of other simulators uses). */
std::vector<std::string> sightingFields(const SimulationOutput& out)
{
	std::vector<std::string> fields;
	for (const TagSighting& s : out.tagSightings)
	{
		char buf[256];
		std::snprintf(buf, sizeof buf,
					  "\"n_points\": %zu, \"n_points_in_square\": %zu, \"points_per_cell\": %.2f, \"n_scans\": %d, "
					  "\"range_min\": %.3f, \"range_max\": %.3f, \"incidence_deg_min\": %.1f",
					  s.points, s.pointsInSquare, s.pointsPerCell, s.scans, s.rangeMin, s.rangeMax, s.incidenceDegMin);
		fields.push_back(buf);
	}
	return fields;
}
}  // namespace

std::string groundTruthMetadata(const SimulationOutput& out, uint64_t seed, const Eigen::Vector3d& shift)
{
	std::ostringstream j;
	j << "\"scene\": " << jsonQuote(out.sceneName) << ", \"seed\": " << seed
	  << ", \"points\": " << out.map.size() << ", \"rays\": " << out.raysCast << ", \"frames\": " << out.frames.size()
	  << ", \"intensity_scale\": " << out.intensityScale << ", \"density_factor\": " << out.densityFactor
	  << ", \"sensors\": [";
	for (size_t i = 0; i < out.sensorNames.size(); i++) j << (i ? ", " : "") << jsonQuote(out.sensorNames[i]);
	j << "], \"tag_points\": [";
	for (size_t i = 0; i < out.truth.size(); i++)
		j << (i ? ", " : "") << "{\"family\": " << jsonQuote(out.truth[i].family) << ", \"id\": " << out.truth[i].id
		  << ", \"points\": " << out.tagSightings[i].points << "}";
	// Where the drifted map shows each tag (see SimulationOutput::truthInMap).
	j << "], \"tags_in_map\": [";
	char num[64];
	for (size_t i = 0; i < out.truthInMap.size(); i++)
	{
		const TagDetection& t = out.truthInMap[i];
		j << (i ? ", " : "") << "{\"family\": " << jsonQuote(t.family) << ", \"id\": " << t.id << ", \"corners\": [";
		for (int v = 0; v < 4; v++)
		{
			const Eigen::Vector3d c = t.corners[v] + shift;
			std::snprintf(num, sizeof num, "[%.6f, %.6f, %.6f]", c.x(), c.y(), c.z());
			j << (v ? ", " : "") << num;
		}
		j << "]}";
	}
	j << "]";
	return j.str();
}

mrpt::maps::CSimpleMap toSimpleMap(const SimulationOutput& out)
{
	mrpt::maps::CSimpleMap sm;
	for (const FrameData& fd : out.frames)
	{
		auto cloud = mrpt::maps::CPointsMapXYZI::Create();
		cloud->resize(fd.pointCount);
		for (size_t i = 0; i < fd.pointCount; i++)
		{
			const SimPoint& p = out.points[fd.firstPoint + i];
			cloud->setPointFast(i, p.local.x(), p.local.y(), p.local.z());
			cloud->setPointIntensity(i, static_cast<float>(p.intensity01 * out.intensityScale));
		}
		cloud->mark_as_modified();
		auto obs = mrpt::obs::CObservationPointCloud::Create();
		obs->pointcloud = cloud;
		obs->sensorLabel = fd.sensorName;
		obs->timestamp = mrpt::Clock::fromDouble(fd.stamp);
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(obs);
		auto pose = mrpt::poses::CPose3DPDFGaussian::Create();
		pose->mean = toMrpt(fd.driftedPose);
		sm.insert(pose, sf);
	}
	return sm;
}

std::string tumTrajectory(const SimulationOutput& out, bool drifted)
{
	std::string s;
	char line[256];
	for (const FrameData& fd : out.frames)
	{
		const Eigen::Isometry3d& T = drifted ? fd.driftedPose : fd.truePose;
		const Eigen::Quaterniond q(T.linear());
		const Eigen::Vector3d t = T.translation();
		std::snprintf(line, sizeof(line), "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", fd.stamp, t.x(), t.y(), t.z(),
					  q.x(), q.y(), q.z(), q.w());
		s += line;
	}
	return s;
}

void writeSimulationOutputs(const std::string& dir, const SimulationOutput& out, const WriteOptions& options)
{
	const std::filesystem::path d(dir);
	checkOutputWritable((d / "map.pcd").string());
	io::savePcdBinary((d / "map.pcd").string(), out.map, options.shift);
	if (options.lasFormat >= 0)
	{
		io::LasWriteParams las;
		las.pointFormat = options.lasFormat;
		las.shift = options.shift;
		io::saveLas((d / "map.las").string(), out.map, las);
	}
	writeTagsJson((d / "ground_truth.json").string(), translatedTags(out.truth, options.shift),
				  groundTruthMetadata(out, options.seed, options.shift), sightingFields(out));
	if (options.simplemap)
	{
		const mrpt::maps::CSimpleMap sm = toSimpleMap(out);
		writeFileAtomicallyByName((d / "scans.simplemap").string(), [&](const std::string& tmp) {
			if (!sm.saveToFile(tmp)) throw InputError(tmp, "", "cannot write simplemap");
		});
	}
	if (!options.simplemap && !options.trajectories) return;
	for (bool drifted : {false, true})
	{
		const std::string text = tumTrajectory(out, drifted);
		writeFileAtomically((d / (drifted ? "trajectory_drifted.tum" : "trajectory_true.tum")).string(),
							[&](std::ostream& o) { o << text; });
	}
}

}  // namespace tagmap::sim
