// `tagmap simulate SCENE.yaml --out DIR [...]`: a thin shell over tagmap_sim.
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/report/progress_printer.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/sim_outputs.h"
#include "tagmap/sim/sim_rawlog.h"
#include "tagmap/sim/simulate.h"

namespace tagmap::app
{
namespace
{
const char* kUsage =
	"Usage: tagmap simulate SCENE.yaml --out DIR [--seed N] [--intensity-scale 1|255|65535]\n"
	"                       [--points N] [--param NAME=VALUE] [--threads N] [--simplemap]\n"
	"                       [--run NAME] [--rawlog FILE] [--las FORMAT] [--shift X,Y,Z] [--quiet]\n"
	"Simulates LiDAR scans of a YAML scene and writes DIR/map.pcd and DIR/ground_truth.json;\n"
	"with --simplemap also DIR/scans.simplemap, DIR/trajectory_true.tum, DIR/trajectory_drifted.tum.\n"
	"  --points N        rescale the sensors' density for a map of about N points\n"
	"  --param NAME=V    override a scene parameter (e.g. tag_distance=4 for accuracy.yaml);\n"
	"                    repeat it for several (--param robot_beams=64 --param robot_columns=512)\n"
	"  --run NAME        simulate only this run of the scene\n"
	"  --rawlog FILE     also write an MRPT rawlog (odometry + scans) and DIR/trajectory_true.tum\n"
	"  --las FORMAT      also write DIR/map.las, LAS point format 0..10 (1.2 for 0-3, else 1.4), 1 mm steps\n"
	"  --shift X,Y,Z     add this to map.pcd (then float64 x y z), map.las and ground_truth.json:\n"
	"                    a georeferenced copy, e.g. 512345,5123456,187 (simplemap, rawlog unshifted)\n"
	"  --quiet           print nothing but errors (default: progress on stderr and a summary line)\n";

// Every --param NAME=VALUE given (a later one of the same NAME wins).
sim::SceneParameters parseParams(const std::vector<std::string>& given)
{
	sim::SceneParameters params;
	for (const std::string& s : given)
	{
		const auto eq = s.find('=');
		if (eq == std::string::npos || eq == 0) throw cli::UsageError("--param: expected NAME=VALUE, got '" + s + "'");
		cli::Args tmp;
		tmp.options["--param"] = s.substr(eq + 1);
		params[s.substr(0, eq)] = tmp.getDouble("--param", 0);
	}
	return params;
}
}  // namespace

int runSimulate(int argc, char** argv)
{
	return cli::runCommand("simulate", [&] {
		const cli::Args a = cli::parse(argc, argv, 1, {"--out", "--seed", "--intensity-scale", "--points", "--param", "--threads", "--run", "--rawlog", "--las", "--shift"},
									   {"--simplemap", "--quiet", "--help"});
		if (a.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (a.positional.size() != 1 || !a.has("--out")) throw cli::UsageError("needs one SCENE.yaml and --out DIR");
		sim::SimOptions opt;
		const long seed = a.getInt("--seed", 1);
		const long points = a.getInt("--points", 0);
		const long threads = a.getInt("--threads", 0);
		if (seed < 0) throw cli::UsageError("--seed must be >= 0");
		if (points < 0) throw cli::UsageError("--points must be >= 0");
		if (threads < 0) throw cli::UsageError("--threads must be >= 0");
		opt.seed = static_cast<uint64_t>(seed);
		opt.targetPoints = static_cast<size_t>(points);
		opt.threads = static_cast<unsigned>(threads);
		opt.intensityScale = a.getDouble("--intensity-scale", 1);
		if (!(opt.intensityScale > 0)) throw cli::UsageError("--intensity-scale must be > 0");
		const long lasFormat = a.getInt("--las", -1);
		if (a.has("--las") && (lasFormat < 0 || lasFormat > 10)) throw cli::UsageError("--las: the LAS point format is 0..10");
		const Eigen::Vector3d shift = a.getVector3("--shift", Eigen::Vector3d::Zero());

		sim::Scene scene =
			sim::loadScene(a.positional[0], parseParams(a.getAll("--param")));
		if (a.has("--run"))
		{
			auto& runs = scene.runs;
			runs.erase(std::remove_if(runs.begin(), runs.end(), [&](const sim::ScanRun& r) { return r.name != a.get("--run"); }),
					   runs.end());
			if (scene.runs.empty()) throw cli::UsageError("--run: the scene has no run '" + a.get("--run") + "'");
		}
		// Fail on an unwritable output now, not after the simulation.
		checkOutputWritable((std::filesystem::path(a.get("--out")) / "map.pcd").string());
		const bool quiet = a.has("--quiet");
		report::ProgressPrinter progress(report::ProgressParams::unlessQuiet(quiet));
		progress.update("casting rays", 0, 0);
		const sim::SimulationOutput out =
			sim::simulate(scene, opt, [&](size_t done, size_t total) { progress.update("casting rays", done, total); });
		progress.update("writing", 0, 0);
		sim::WriteOptions wo;
		wo.simplemap = a.has("--simplemap");
		wo.seed = opt.seed;
		wo.lasFormat = static_cast<int>(lasFormat);
		wo.shift = shift;
		sim::writeSimulationOutputs(a.get("--out"), out, wo);
		if (a.has("--rawlog"))
			sim::writeSimulationRawlog(a.get("--rawlog"),
									   (std::filesystem::path(a.get("--out")) / "trajectory_true.tum").string(), out);
		progress.finish();
		if (quiet) return 0;

		std::cout << "scene " << out.sceneName << ": " << out.map.size() << " points from " << out.frames.size()
				  << " frames, " << out.truth.size() << " tags";
		for (size_t i = 0; i < out.truth.size(); i++)
			std::cout << (i ? ", " : " (") << out.truth[i].family << ":" << out.truth[i].id << " " << out.tagSightings[i].points
					  << " pts" << (i + 1 == out.truth.size() ? ")" : "");
		std::cout << ", " << out.seconds << " s -> " << a.get("--out") << "\n";
		return 0;
	});
}
}  // namespace tagmap::app
