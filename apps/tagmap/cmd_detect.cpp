// tagmap detect: point-cloud map in, tags (family, id, corners, pose) out.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "detect_outputs.h"
#include "pipeline_args.h"
#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/local_frame.h"
#include "tagmap/io/point_cloud_io.h"
#include "tagmap/localize/trajectory_tum.h"
#include "tagmap/pipeline.h"
#include "tagmap/report/progress_printer.h"
#include "tagmap/report/report_writer.h"
#include "tagmap/tag_table.h"
#include "tagmap/tags_json.h"
#include "tagmap/verdict.h"
#include "tagmap/voxel_grid.h"

namespace tagmap::app
{
namespace
{
std::string usage()
{
	return std::string(
			   "Usage: tagmap detect INPUT --json OUT [options]\n"
			   "\n"
			   "Finds fiducial tags (AprilTag, ArUco) in a 3D LiDAR map with intensity and\n"
			   "writes each tag's family, id, size, 4 indexed corners and 6-DoF pose.\n"
			   "\n"
			   "INPUT: ") +
		   io::supportedExtensions() +
		   "\n"
		   "\n"
		   "Options:\n"
		   "  --json OUT         result file (docs/RESULT_FORMAT.md), written atomically (required)\n"
		   "  --report DIR       also write DIR/index.html: the map with the tags marked, every\n"
		   "                     candidate's image and why it was rejected, timings (default: none)\n"
		   "  --landmarks F      mrpt::maps::CLandmarksMap, one beacon per tag (.gz MRPT serialization)\n"
		   "  --tagmap F         tagmap::maps::CTagMap with the tags and the points (load the plugin)\n"
		   "  --ini F            [MetricMap] section with the tags as beacons, for pf-localization\n"
		   "  --rawlog F         RawLogViewer file: the map and the tags as a CObservation3DScene\n"
		   "  --3dscene F        SceneViewer3D file: the map coloured by intensity, the tags drawn\n"
		   "  --origin X,Y,Z     local origin to subtract from the file's coordinates (default: the\n"
		   "                     map's median rounded to metres, 0 on axes within 1 km of 0)\n"
		   "  --viewpoints TRAJ  the sensor poses the map was built from, as TUM lines (t x y z qx qy\n"
		   "                     qz qw, the file's frame: e.g. a SLAM system's trajectory): a read\n"
		   "                     whose printed face none of them could see is rejected (a .simplemap\n"
		   "                     or .rawlog input brings its own; default: none for point clouds);\n"
		   "                     a trajectory with no position within 1 km of the map is an error\n" +
		   pipelineOptionsHelp() +
		   "  --quiet            print nothing but errors (default: progress and a table of tags)\n"
		   "  --verbose          also print per-stage timings and counts\n"
		   "  --help             this text\n"
		   "\n"
		   "Progress goes to stderr: a bar on a terminal, a line every 2 s otherwise.\n"
		   "\n"
		   "Georeferenced maps (UTM, ECEF): coordinates are read in double (PCD/PLY float64,\n"
		   "LAS scaled integers), a local origin is subtracted before they are stored as\n"
		   "float, and detection runs in that local frame; the origin is printed. The JSON and\n"
		   "the printed table are in the file's frame (double precision). MRPT outputs are in the\n"
		   "local frame: MRPT stores points as float, and CLandmarksMap (--landmarks, and\n"
		   "pf-localization from --ini) grids its landmarks from 0, which cannot reach UTM\n"
		   "coordinates; --3dscene and --rawlog name the origin in the cloud's name.\n"
		   "Points more than 1e7 m from the origin or not finite are skipped (counted); if\n"
		   "none is left, detect fails.\n"
		   "LAZ: decompress first (laszip, PDAL).\n";
}

// A trajectory in another frame than the map's (UTM against local, a SLAM
// system's odometry frame) would point every line of sight the wrong way and
// reject real tags as seen from behind. Each point was measured from a
// sensor position within the LiDAR's range of it, and that range is below
// a kilometre: a trajectory with no position within 1 km of the map's
// bounds (or the map's own size, for larger maps) is in another frame.
void checkTrajectoryNearMap(const std::string& path, const std::vector<Eigen::Vector3d>& positions,
							const mrpt::maps::CPointsMapXYZI& map)
{
	if (positions.empty() || map.empty()) return;
	Eigen::Vector3d lo, hi;
	pointBounds(map.getPointsBufferRef_x().data(), map.getPointsBufferRef_y().data(), map.getPointsBufferRef_z().data(),
				map.size(), 0, lo, hi);
	const double reach = std::max(1000.0, (hi - lo).norm());
	double nearest = std::numeric_limits<double>::infinity();
	for (const Eigen::Vector3d& p : positions)
		nearest = std::min(nearest, (p.cwiseMax(lo).cwiseMin(hi) - p).norm());
	if (nearest > reach)
		throw InputError(path, "", "no sensor position within " + std::to_string(static_cast<long long>(reach)) +
									   " m of the map (the nearest is " + std::to_string(static_cast<long long>(nearest)) +
									   " m off): the trajectory must be in the map's frame");
}

std::string skippedSummary(const io::LoadReport& load)
{
	return "read " + std::to_string(load.pointsRead) + " points; skipped " + std::to_string(load.nonFiniteSkipped) +
		   " non-finite (NaN/Inf coordinate or intensity), skipped " + std::to_string(load.outOfRangeSkipped) +
		   " out of range (more than " + std::to_string(static_cast<long long>(io::kMaxAbsCoordinate)) +
		   " m from the local origin)";
}

std::string joinArgs(int argc, char** argv)
{
	std::string s = "tagmap";
	for (int i = 0; i < argc; i++) s += std::string(" ") + argv[i];
	return s;
}

void printTable(const Detections& found, const Eigen::Vector3d& origin)
{
	TagTableColumns columns;
	columns.points = true;
	std::fputs(tagTable(translatedTags(found.tags, origin), columns).c_str(), stdout);
}

void printStages(const Detections& found)
{
	std::fprintf(stderr, "%-20s %9s %12s %12s\n", "stage", "seconds", "in", "out");
	for (const auto& s : found.stages)
		std::fprintf(stderr, "%-20s %9.3f %12zu %12zu\n", s.name.c_str(), s.seconds, s.itemsIn, s.itemsOut);
	std::fprintf(stderr, "%-20s %9.3f\n", "total", found.totalSeconds);
	std::fprintf(stderr, "measured: point spacing %.1f mm, surface noise %.1f mm\n", 1000 * found.pointSpacing,
				 1000 * found.surfaceNoise);
	// What became of the clusters and windows: where the decode time went.
	std::vector<size_t> count(kVerdicts.size(), 0);
	for (const auto& c : found.candidates) count[static_cast<size_t>(c.verdict)]++;
	std::fprintf(stderr, "verdicts:");
	for (const VerdictInfo& v : kVerdicts)
		if (count[static_cast<size_t>(v.verdict)]) std::fprintf(stderr, " %s %zu", v.name, count[static_cast<size_t>(v.verdict)]);
	std::fprintf(stderr, "\n");
}
}  // namespace

int runDetect(int argc, char** argv)
{
	return cli::runCommand("detect", [&] {
		const cli::Args args =
			cli::parse(argc, argv, 1, with(with(pipelineOptions(), mrptOutputOptions()), {"--json", "--report", "--origin", "--viewpoints"}),
					   {"--quiet", "--verbose", "--help"});
		if (args.has("--help"))
		{
			std::cout << usage();
			return 0;
		}
		if (args.positional.size() != 1) throw cli::UsageError("expected exactly one INPUT file");
		if (!args.has("--json")) throw cli::UsageError("--json OUT is required");
		const std::string input = args.positional[0], jsonPath = args.get("--json"), reportDir = args.get("--report");
		DetectionUsed used;
		used.choices = detectionChoicesFromArgs(args);
		used.params = resolveDetectionSettings(used.choices);
		const PipelineParams& params = used.params;
		const bool quiet = args.has("--quiet"), verbose = args.has("--verbose");

		// Fail on an unwritable output now, not after minutes of work.
		checkOutputWritable(jsonPath);
		if (!reportDir.empty()) report::checkReportDir(reportDir);
		checkMrptOutputs(args);
		// Read before the map, so a bad trajectory fails at once.
		const std::vector<Eigen::Vector3d> trajectory =
			args.has("--viewpoints") ? localize::readTumPositions(args.get("--viewpoints")) : std::vector<Eigen::Vector3d>{};

		report::ProgressPrinter progress(report::ProgressParams::unlessQuiet(quiet));
		progress.update("reading", 0, 0);

		io::LoadReport load;
		load.progress = [&](size_t pointsSoFar) { progress.update("reading", pointsSoFar, 0); };
		io::LoadParams loadParams;
		loadParams.fixedOrigin = args.has("--origin");
		loadParams.origin = args.getVector3("--origin", Eigen::Vector3d::Zero());
		const mrpt::maps::CPointsMapXYZI map = io::loadPointCloud(input, &load, loadParams);
		progress.update("reading", map.size(), map.size());
		const Eigen::Vector3d& origin = load.origin;
		// Nothing usable is the input's fault, and an empty result would
		// read as "no tags here": fail, saying what happened to the points.
		if (load.pointsKept == 0) throw InputError(input, "", "no usable point: " + skippedSummary(load));
		// A simplemap's or rawlog's sensor positions: a read whose printed
		// face none of them could see is a mirror image (front_side.h).
		used.viewpoints = load.localViewpoints();
		std::vector<Eigen::Vector3d> trajectoryHere;  // in the map's local frame
		for (const Eigen::Vector3d& p : trajectory) trajectoryHere.push_back(p - origin);
		checkTrajectoryNearMap(args.get("--viewpoints"), trajectoryHere, map);
		used.viewpoints.insert(used.viewpoints.end(), trajectoryHere.begin(), trajectoryHere.end());
		if (!quiet)
		{
			std::fprintf(stderr, "tagmap: read %zu points from %s (%s, intensity from '%s'), local origin %.3f %.3f %.3f",
						 load.pointsKept, input.c_str(), load.format.c_str(), load.intensityField.c_str(), origin.x(),
						 origin.y(), origin.z());
			if (load.nonFiniteSkipped + load.outOfRangeSkipped) std::fprintf(stderr, "; %s", skippedSummary(load).c_str());
			// Said, so a user knows the sensors' lines of sight are judged.
			if (!used.viewpoints.empty()) std::fprintf(stderr, "; %zu sensor positions", used.viewpoints.size());
			std::fprintf(stderr, "\n");
		}
		const Pipeline pipeline(params);
		const Detections found = [&] {
			// The pipeline refuses maps it cannot index (a stray point 900 km
			// from the rest): the input's fault, so the message names it.
			try
			{
				return pipeline.detect(map, used.viewpoints, progress.callback(), !reportDir.empty());
			}
			catch (const std::invalid_argument& e)
			{
				throw InputError(input, "", e.what());
			}
		}();
		writeTagsJson(jsonPath, translatedTags(found.tags, origin));
		writeMrptOutputs(args, used, map, found, origin);
		if (!quiet && !origin.isZero() && std::any_of(mrptOutputOptions().begin(), mrptOutputOptions().end(),
													  [&](const std::string& o) { return args.has(o); }))
			std::fprintf(stderr, "tagmap: the MRPT outputs are in the local frame: add the local origin %.3f %.3f %.3f\n",
						 origin.x(), origin.y(), origin.z());
		if (!reportDir.empty())
		{
			progress.update("report", 0, 0);
			report::writeReport(reportDir, {input, load.format + ", intensity from '" + load.intensityField + "'",
											joinArgs(argc, argv), map, found, params});
			progress.update("report", 1, 1);
		}
		progress.finish();
		if (!quiet)
		{
			printTable(found, origin);
			std::fprintf(stderr, "tagmap: %zu tag(s) in %.2f s -> %s\n", found.tags.size(), found.totalSeconds,
						 jsonPath.c_str());
			if (!reportDir.empty()) std::fprintf(stderr, "tagmap: report -> %s/index.html\n", reportDir.c_str());
		}
		if (verbose) printStages(found);
		return 0;
	});
}

}  // namespace tagmap::app
