// `tagmap localize --map TAGS.json --rawlog OBS.rawlog --method pf|direct
// --out TRAJ.tum [--truth TRUE.tum --errors ERR.json]`: a thin shell over
// tagmap_localize (docs/LOCALIZATION.md).
#include <mrpt/obs/CRawlog.h>

#include <cstdio>
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/localize/direct_localizer.h"
#include "tagmap/localize/pf_localizer.h"
#include "tagmap/io/rawlog_file.h"
#include "tagmap/localize/trajectory_errors.h"
#include "tagmap/report/progress_printer.h"
#include "tagmap/tags_json.h"

namespace tagmap::app
{
namespace
{
const char* kUsage =
	"Usage: tagmap localize --map TAGS.json --rawlog OBS.rawlog --method pf|direct --out TRAJ.tum\n"
	"                       [--truth TRUE.tum [--errors ERR.json]] [--particles N] [--seed N]\n"
	"                       [--model poses|ranges] [--no-odometry] [--quiet]\n"
	"Localizes the LiDAR of OBS.rawlog (written by `tagmap observe`) in the tag map TAGS.json\n"
	"(a `tagmap detect` result) and writes the sensor poses as TUM lines.\n"
	"  --method pf       MRPT's particle filter (CMonteCarloLocalization2D) on the tag map\n"
	"                    (CTagMap), from a uniform belief over the map, with odometry (actions\n"
	"                    or CObservationOdometry; none is an error unless --no-odometry)\n"
	"  --method direct   T_G_sensor = T_G_tag * T_sensor_tag^-1 per scan, fused over the\n"
	"                    visible tags; scans without a mapped tag get no pose\n"
	"  --truth TRUE.tum  score against ground truth (poses paired by time stamp) and print\n"
	"                    rmse_translation_m, rmse_rotation_deg, converged_at_step as JSON\n"
	"  --errors ERR.json also write that JSON\n"
	"  --particles N     particles of the global (uniform) phase (default 40000)\n"
	"  --seed N          random seed of the particle filter (default 1)\n"
	"  --model M         pf observation model: poses (each tag's 6-DoF pose, default) or\n"
	"                    ranges (range-only beacons)\n"
	"  --no-odometry     pf without odometry: zero increments, motion noise for up to\n"
	"                    1 m/s and 30 deg/s over the time between scans\n"
	"  --quiet           no progress and no summary line (the errors JSON is still printed)\n";

}  // namespace

int runLocalize(int argc, char** argv)
{
	return cli::runCommand("localize", [&] {
		const cli::Args a = cli::parse(argc, argv, 1,
									   {"--map", "--rawlog", "--method", "--out", "--truth", "--errors", "--particles",
										"--seed", "--model"},
									   {"--quiet", "--help", "--no-odometry"});
		if (a.has("--help"))
		{
			std::cout << kUsage;
			return 0;
		}
		if (!a.positional.empty()) throw cli::UsageError("unexpected argument '" + a.positional[0] + "'");
		for (const char* required : {"--map", "--rawlog", "--method", "--out"})
			if (!a.has(required)) throw cli::UsageError(std::string("missing ") + required);
		const std::string method = a.get("--method");
		if (method != "pf" && method != "direct") throw cli::UsageError("--method must be pf or direct");
		if (a.has("--errors") && !a.has("--truth")) throw cli::UsageError("--errors needs --truth");
		localize::PfParams pf;
		const long particles = a.getInt("--particles", static_cast<long>(pf.globalParticles));
		const long seed = a.getInt("--seed", pf.seed);
		// 10^7 particles are ~1 GB and minutes per step: more is a typo.
		if (particles < 100 || particles > 10000000)
			throw cli::UsageError("--particles must be between 100 and 10000000");
		if (seed < 0 || seed > 4294967295L) throw cli::UsageError("--seed must be between 0 and 4294967295");
		const std::string model = a.has("--model") ? a.get("--model") : "poses";
		if (model != "poses" && model != "ranges") throw cli::UsageError("--model must be poses or ranges");
		if ((a.has("--model") || a.has("--no-odometry")) && method != "pf")
			throw cli::UsageError("--model and --no-odometry are for --method pf");
		pf.observations = model == "poses" ? localize::PfObservations::tagPoses : localize::PfObservations::ranges;
		pf.noOdometry = a.has("--no-odometry");
		pf.globalParticles = static_cast<size_t>(particles);
		pf.seed = static_cast<uint32_t>(seed);

		const std::vector<TagDetection> mapTags = readTagsJson(a.get("--map"));
		if (mapTags.empty()) throw InputError(a.get("--map"), "", "no tags: nothing to localize against");
		const localize::Trajectory truth = a.has("--truth") ? localize::readTum(a.get("--truth")) : localize::Trajectory{};
		checkOutputWritable(a.get("--out"));
		if (a.has("--errors")) checkOutputWritable(a.get("--errors"));

		const bool quiet = a.has("--quiet");
		report::ProgressPrinter progress(report::ProgressParams::unlessQuiet(quiet));
		progress.update("reading", 0, 0);
		const localize::OdometryUse odometry = method == "direct" ? localize::OdometryUse::optional
											   : pf.noOdometry	  ? localize::OdometryUse::ignored
																  : localize::OdometryUse::required;
		const auto steps = localize::localizationSteps(io::loadRawlog(a.get("--rawlog")), a.get("--rawlog"), odometry);
		progress.update("reading", steps.size(), steps.size());
		localize::Trajectory estimate;
		std::string extra = "\"method\": \"" + method + "\", \"steps\": " + std::to_string(steps.size());
		if (method == "pf")
		{
			const localize::PfResult r = localize::runParticleFilter(
				mapTags, steps, pf, [&](size_t done, size_t total) { progress.update("particle filter", done, total); });
			estimate = r.trajectory;
			extra += ", \"pf_converged_at_step\": " + std::to_string(r.convergedAtStep);
		}
		else
			estimate = localize::runDirectLocalization(mapTags, steps).trajectory;
		progress.update("writing", 0, 0);
		localize::writeTum(a.get("--out"), estimate);
		progress.finish();
		if (!quiet)
			std::printf("%s: %zu steps, %zu poses -> %s\n", method.c_str(), steps.size(), estimate.size(),
						a.get("--out").c_str());

		if (a.has("--truth"))
		{
			const std::string json =
				localize::errorsToJson(localize::evaluateTrajectory(estimate, truth), extra);
			std::cout << json;
			if (a.has("--errors")) writeFileAtomically(a.get("--errors"), [&](std::ostream& o) { o << json; });
		}
		return 0;
	});
}
}  // namespace tagmap::app
