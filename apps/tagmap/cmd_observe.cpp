// `tagmap observe IN.rawlog OUT.rawlog`: a thin shell over
// tagmap::localize::observeRawlog (docs/LOCALIZATION.md).
#include <mrpt/obs/CRawlog.h>

#include <cstdio>
#include <iostream>

#include "cli.h"
#include "commands.h"
#include "pipeline_args.h"
#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/localize/observe_rawlog.h"
#include "tagmap/io/rawlog_file.h"
#include "tagmap/localize/scan_tags.h"
#include "tagmap/report/progress_printer.h"

namespace tagmap::app
{
namespace
{
const char* kUsage =
	"Usage: tagmap observe IN.rawlog OUT.rawlog [--family F] [--tag-size S] [--config FILE]\n"
	"                      [--window N [--max-window M]] [--sensor-view | --map-path] [--threads N] [--quiet]\n"
	"Detects the tags in every LiDAR scan of IN (sensor frame) and writes OUT: IN with,\n"
	"next to each scan, a CObservationBeaconRanges (range to each tag centre, beacon IDs\n"
	"as in docs/MRPT.md) and a tagmap::obs::CObservationTagPoses (T_sensor_tag + 6x6\n"
	"covariance; RawLogViewer -l build/lib/libtagmap_mrpt_plugin.so shows it).\n"
	"Without --config the single-scan parameters are used (docs/LOCALIZATION.md); with it,\n"
	"the file's sensor_view.enabled chooses the path unless a flag below does.\n"
	"  --window N       detect on each scan merged with the N-1 scans before it, placed by the\n"
	"                   rawlog's odometry (default 1: every scan alone). For short frames too\n"
	"                   sparse to decode a tag (a 0.1 s Livox frame): e.g. 3-5 (docs/LOCALIZATION.md)\n"
	"  --max-window M   a scan whose window of N shows no tag is detected again merged with up\n"
	"                   to M-1 scans before it: the frames between tags get a sighting with the\n"
	"                   longer window's larger covariance (M > N >= 2; default: no second try)\n"
	"  --sensor-view    candidates from each scan's own spherical view, read by the decoders\n"
	"                   (the default with --window 1: one scan, one viewpoint; with a window,\n"
	"                   only over slow motion: docs/LOCALIZATION.md)\n"
	"  --map-path       candidates from the 3D intensity gradient, as `detect` finds them (the\n"
	"                   default with a --window above 1)\n"
	"  --quiet          print nothing but errors (default: progress on stderr and a summary line)\n";

}  // namespace

int runObserve(int argc, char** argv)
{
	return cli::runCommand("observe", [&] {
		const cli::Args a =
			cli::parse(argc, argv, 1, with(pipelineOptions(), {"--window", "--max-window"}), {"--help", "--quiet", "--sensor-view", "--map-path"});
		if (a.has("--help"))
		{
			std::cout << kUsage << pipelineOptionsHelp();
			return 0;
		}
		if (a.positional.size() != 2) throw cli::UsageError("expected IN.rawlog and OUT.rawlog");
		const std::string in = a.positional[0], out = a.positional[1];
		const long window = a.getInt("--window", 1);
		// 100 frames of a 10 Hz sensor are 10 s: odometry drift no longer small.
		if (window < 1 || window > 100) throw cli::UsageError("--window must be 1-100 scans");
		const long maxWindow = a.getInt("--max-window", 0);
		// One scan is detected in its own sensor view, which a merged window is not.
		if (a.has("--max-window") && (window < 2 || maxWindow <= window || maxWindow > 100))
			throw cli::UsageError("--max-window must be above --window (2 or more) and at most 100 scans");
		if (a.has("--sensor-view") && a.has("--map-path")) throw cli::UsageError("--sensor-view or --map-path, not both");
		// The window's parameters unless a config file replaces them; the flags win.
		PipelineParams params = pipelineParamsFromArgs(a, localize::singleScanPipelineParams(static_cast<size_t>(window)));
		if (a.has("--sensor-view")) params.sensorView.enabled = true;
		if (a.has("--map-path")) params.sensorView.enabled = false;
		checkOutputWritable(out);
		localize::keepScanMemoryForReuse();
		const bool quiet = a.has("--quiet");
		report::ProgressPrinter progress(report::ProgressParams::unlessQuiet(quiet));
		progress.update("reading", 0, 0);
		const mrpt::obs::CRawlog log = io::loadRawlog(in);
		progress.update("reading", log.size(), log.size());
		localize::ObserveParams observeParams;
		observeParams.window = static_cast<size_t>(window);
		observeParams.maxWindow = static_cast<size_t>(maxWindow);
		localize::ObserveReport report;
		const mrpt::obs::CRawlog observed = localize::observeRawlog(
			log, Pipeline(params), observeParams, &report, [&](size_t done, size_t total) { progress.update("scans", done, total); });
		if (report.scans == 0) throw InputError(in, "", "no LiDAR observation with intensity");
		progress.update("writing", 0, 0);
		io::saveRawlog(out, observed);
		progress.finish();
		if (quiet) return 0;
		const std::string longWindow = observeParams.maxWindow > observeParams.window
											? " (" + std::to_string(report.scansWithTagsInLongWindow) + " by the longer window)"
											: "";
		std::printf("%zu scans, %zu with tags%s, %zu tag sightings, %.1f s (detection: median %.1f ms per scan) -> %s\n",
					report.scans, report.scansWithTags, longWindow.c_str(), report.tagsSeen, report.seconds,
					1000 * report.medianDetectSeconds(), out.c_str());
		std::string perTag;
		for (const auto& [tag, scans] : report.scansPerTag) perTag += " " + tag + " (" + std::to_string(scans) + ")";
		std::printf("scans per tag:%s\n", perTag.empty() ? " none" : perTag.c_str());
		return 0;
	});
}
}  // namespace tagmap::app
