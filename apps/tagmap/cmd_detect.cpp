// tagmap detect: point-cloud map in, tags (family, id, corners, pose) out.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/pipeline.h"
#include "tagmap/tag_family.h"
#include "tagmap/tags_json.h"

namespace tagmap::app
{
namespace
{
const char* kUsage =
	"Usage: tagmap detect INPUT --json OUT [options]\n"
	"\n"
	"Finds fiducial tags (AprilTag, ArUco) in a 3D LiDAR map with intensity and\n"
	"writes each tag's family, id, size, 4 indexed corners and 6-DoF pose.\n"
	"\n"
	"INPUT: .pcd (ascii/binary/binary_compressed), .ply, .bin (KITTI), .xyzi/.txt,\n"
	"       .simplemap, .rawlog\n"
	"\n"
	"Options:\n"
	"  --json OUT         result file (CONVENTIONS.md schema); written atomically\n"
	"  --family F[,F...]  families to look for (default: all supported)\n"
	"  --tag-size S       tag border-square edge in metres (default: any size in\n"
	"                     [candidates.min_tag_size, candidates.max_tag_size])\n"
	"  --config FILE      YAML parameters (see share/config/default.yaml); flags win\n"
	"  --threads N        worker threads (default: all cores); results do not depend on N\n"
	"  --quiet            print nothing but errors\n"
	"  --verbose          also print per-stage timings and counts\n"
	"  --help             this text\n";

void printTable(const Detections& found)
{
	std::printf("%-16s %5s %7s %28s %24s %7s\n", "family", "id", "size", "position x y z [m]",
				"roll pitch yaw [deg]", "points");
	for (const auto& t : found.tags)
	{
		const Eigen::Vector3d p = t.position();
		const Eigen::Vector3d rpy = rollPitchYaw(t.pose.linear()) * 180.0 / M_PI;
		std::printf("%-16s %5d %7.3f %9.3f %9.3f %9.3f %8.2f %7.2f %7.2f %7d\n", t.family.c_str(), t.id, t.size, p.x(),
					p.y(), p.z(), rpy.x(), rpy.y(), rpy.z(), t.pointsUsed);
	}
}

void printStages(const Detections& found)
{
	std::fprintf(stderr, "%-20s %9s %12s %12s\n", "stage", "seconds", "in", "out");
	for (const auto& s : found.stages)
		std::fprintf(stderr, "%-20s %9.3f %12zu %12zu\n", s.name.c_str(), s.seconds, s.itemsIn, s.itemsOut);
	std::fprintf(stderr, "%-20s %9.3f\n", "total", found.totalSeconds);
}
}  // namespace

int runDetect(int argc, char** argv)
{
	try
	{
		const cli::Args args = cli::parse(argc, argv, 1, {"--json", "--family", "--tag-size", "--config", "--threads"},
										  {"--quiet", "--verbose", "--help"});
		if (args.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (args.positional.size() != 1) throw cli::UsageError("expected exactly one INPUT file");
		if (!args.has("--json")) throw cli::UsageError("--json OUT is required");
		const std::string input = args.positional[0], jsonPath = args.get("--json");

		PipelineParams params = args.has("--config") ? PipelineParams::fromYamlFile(args.get("--config")) : PipelineParams{};
		if (args.has("--family")) params.families = parseFamilyList(args.get("--family"));
		if (args.has("--tag-size"))
		{
			params.tagSize = args.getDouble("--tag-size", 0);
			if (!(params.tagSize > 0)) throw cli::UsageError("--tag-size must be a positive length in metres");
		}
		if (args.has("--threads"))
		{
			const long t = args.getInt("--threads", 0);
			if (t < 1 || t > 1024) throw cli::UsageError("--threads must be between 1 and 1024");
			params.threads = static_cast<unsigned>(t);
		}
		const bool quiet = args.has("--quiet"), verbose = args.has("--verbose");

		// Fail on an unwritable output now, not after minutes of work.
		checkOutputWritable(jsonPath);

		io::LoadReport load;
		const mrpt::maps::CPointsMapXYZI map = io::loadPointCloud(input, &load);
		if (!quiet)
		{
			std::fprintf(stderr, "tagmap: read %zu points from %s (%s, intensity from '%s')", load.pointsKept,
						 input.c_str(), load.format.c_str(), load.intensityField.c_str());
			if (load.nonFiniteSkipped) std::fprintf(stderr, ", skipped %zu non-finite", load.nonFiniteSkipped);
			std::fprintf(stderr, "\n");
		}
		const Pipeline pipeline(params);
		const Detections found = pipeline.detect(map);
		writeTagsJson(jsonPath, found.tags);
		if (!quiet)
		{
			printTable(found);
			std::fprintf(stderr, "tagmap: %zu tag(s) in %.2f s -> %s\n", found.tags.size(), found.totalSeconds,
						 jsonPath.c_str());
		}
		if (verbose) printStages(found);
		return 0;
	}
	catch (const cli::UsageError& e)
	{
		std::cerr << "tagmap detect: " << e.what() << " (see tagmap detect --help)\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "tagmap detect: " << e.what() << "\n";
		return 1;
	}
}

}  // namespace tagmap::app
