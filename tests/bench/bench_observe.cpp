// Single-scan rate: `tagmap observe`'s path (rawlog scan -> sensor frame ->
// Pipeline::detect -> tag poses) on simulated robot runs, the pipeline on ONE
// thread, as a robot's localization would run it beside everything else.
// Prints per sensor: points per detection, median and 90th-percentile
// milliseconds, scans per second, the median milliseconds of each stage, and
// what the scans saw against the simulator's truth in the sensor frame
// (sightings, false or wrong-ID reports, pose errors), so a speed-up that
// costs a sighting or accuracy shows.
//
// Sensors (share/scenes/localize_site.yaml, the localization demo's site):
//   spinning  a 64-beam x 512-column LiDAR at 10 Hz (~25 k points a scan)
//   spinning128  the localization demo's 128-beam x 1024-column one (~130 k)
//   spinning32, spinning16  32 and 16 beams x 1024 columns (~33 k, ~16 k): rows
//             far apart, the sensor view's sparsest case
//   livox     the Livox-like rosette, 0.1 s frames (~10 k points), each merged
//             with the 2 before it by the odometry (observe --window 3: ~30 k)
//
//   build/bin/tagmap-bench-observe [--sensor spinning|spinning128|spinning32|spinning16|livox|both] [--scans N]
//                                  [--family LIST] [--seed S] [--window N] [--max-window M] [--misses]
//                                  [--sensor-view | --map-path] [--config FILE]
// `both` is spinning and livox. --config reads the pipeline's parameters
// as `tagmap observe --config` does (the file's sensor_view.enabled chooses
// the path unless --sensor-view or --map-path does), to compare settings. The path is observe's: a single scan's
// candidates from its own view (sensor_view.h), a window's from the map
// path's stages 1-3; --sensor-view and --map-path choose either way.
#include <sched.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <mrpt/obs/CSensoryFrame.h>

#include "tagmap/detection_settings.h"
#include "tagmap/evaluation.h"
#include "tagmap/localize/observe_rawlog.h"
#include "tagmap/localize/rawlog_visit.h"
#include "tagmap/localize/scan_tags.h"
#include "tagmap/obs/CObservationTagPoses.h"
#include "tagmap/quantile.h"
#include "tagmap/sim/scene_loader.h"
#include "tagmap/sim/sim_rawlog.h"
#include "tagmap/sim/simulate.h"
#include "tagmap/tag_family.h"

using namespace tagmap;

namespace
{
struct Options
{
	std::string sensor = "both";
	size_t scans = 0;  // 0: the whole run
	std::string families = "tag36h11";
	uint64_t seed = 1;
	size_t window = 0;  // 0: each sensor's own (spinning 1, Livox 3)
	size_t maxWindow = 0;  // observe --max-window (0: none)
	bool misses = false;  // explain every tag with points in the window that was not seen
	std::string path;  // "sensor-view" or "map-path" when chosen; observe's default otherwise
	std::string config;  // YAML parameters over the built-in defaults, as observe --config
};

struct SensorRun
{
	std::string label, run;
	std::map<std::string, double> params;
	size_t window;
};

// The error against the detection's own covariance: sqrt(e' C^-1 e / 3)
// for position and for rotation (the covariance's convention: a small-angle
// vector on the left, in the sensor frame). About 0.9 at the median when
// the covariance is honest, far above 1 when it is overconfident; what a
// localizer weighs the tag by.
// Also the position error along each axis of the true tag's frame (x
// right, y up, z its normal) over that axis' reported sigma: a sensor whose
// rows lie far apart shows it along one in-plane axis only.
struct NormalizedError
{
	double position = NAN, rotation = NAN;
	Eigen::Vector3d alongTagAxes = Eigen::Vector3d::Constant(NAN);
};
NormalizedError normalizedError(const TagDetection& found, const TagDetection& truth)
{
	const Eigen::Vector3d dp = found.position() - truth.position();
	const Eigen::AngleAxisd aa(found.pose.linear() * truth.pose.linear().transpose());
	const Eigen::Vector3d dr = aa.angle() * aa.axis();
	const Eigen::Matrix3d cp = found.covariance.topLeftCorner<3, 3>(), cr = found.covariance.bottomRightCorner<3, 3>();
	NormalizedError n;
	if (cp.determinant() > 0)
	{
		n.position = std::sqrt(dp.dot(cp.ldlt().solve(dp)) / 3);
		const Eigen::Matrix3d R = truth.pose.linear();
		const Eigen::Matrix3d inTag = R.transpose() * cp * R;
		n.alongTagAxes = (R.transpose() * dp).cwiseAbs().cwiseQuotient(inTag.diagonal().cwiseSqrt());
	}
	if (cr.determinant() > 0) n.rotation = std::sqrt(dr.dot(cr.ldlt().solve(dr)) / 3);
	return n;
}

// NaN for no values (a sensor that saw no tag has no errors to rank).
double quantile(std::vector<double> v, double q) { return v.empty() ? NAN : quantileInPlace(v, q); }

// Pose errors of sightings against the truth in the sensor frame, and
// against each one's reported covariance.
struct SightingErrors
{
	std::vector<double> position, rotation, positionNorm, rotationNorm;
	std::array<std::vector<double>, 3> axisNorm;  // tag x, y, normal

	void add(const TagError& e, const TagDetection& seen, const TagDetection& truth)
	{
		position.push_back(e.positionError.norm());
		rotation.push_back(e.rotationErrorDeg.norm());
		// A detection without a covariance has no normalized error: ranked
		// as NaN it would break the quantiles' ordering.
		const NormalizedError n = normalizedError(seen, truth);
		if (std::isfinite(n.position)) positionNorm.push_back(n.position);
		if (std::isfinite(n.rotation)) rotationNorm.push_back(n.rotation);
		for (int a = 0; a < 3; a++)
			if (std::isfinite(n.alongTagAxes[a])) axisNorm[a].push_back(n.alongTagAxes[a]);
	}
	void print(const std::string& label) const
	{
		std::printf("%s (%zu): error in the sensor frame: position median %.4f m, p90 %.4f m; rotation median "
					"%.3f deg, p90 %.3f deg\n",
					label.c_str(), position.size(), quantile(position, 0.5), quantile(position, 0.9),
					quantile(rotation, 0.5), quantile(rotation, 0.9));
		if (!positionNorm.empty())
			std::printf("  error / reported sigma (sqrt(e' C^-1 e / 3); ~0.9 at the median when honest): position "
						"median %.2f, p90 %.2f; rotation median %.2f, p90 %.2f\n",
						quantile(positionNorm, 0.5), quantile(positionNorm, 0.9), quantile(rotationNorm, 0.5),
						quantile(rotationNorm, 0.9));
		if (!axisNorm[0].empty())
			std::printf("  position |error| / sigma along the tag's x, y, normal (~0.67 at the median when honest): "
						"median %.2f, %.2f, %.2f; p90 %.2f, %.2f, %.2f\n",
						quantile(axisNorm[0], 0.5), quantile(axisNorm[1], 0.5), quantile(axisNorm[2], 0.5),
						quantile(axisNorm[0], 0.9), quantile(axisNorm[1], 0.9), quantile(axisNorm[2], 0.9));
	}
};

// The true tags as the sensor of `frame` sees them: T_sensor_tag.
std::vector<TagDetection> truthInSensorFrame(const std::vector<TagDetection>& truth, const sim::FrameData& frame)
{
	std::vector<TagDetection> out = truth;
	for (TagDetection& t : out)
	{
		t.pose = frame.truePose.inverse() * t.pose;
		t.corners = cornersFromPose(t.pose, t.size);
	}
	return out;
}

// Each scan's CObservationTagPoses, in rawlog order.
std::vector<std::vector<TagDetection>> tagsPerScan(const mrpt::obs::CRawlog& observed)
{
	std::vector<std::vector<TagDetection>> out;
	const auto take = [&](const mrpt::obs::CObservation::Ptr& o) {
		if (auto t = std::dynamic_pointer_cast<obs::CObservationTagPoses>(o)) out.push_back(t->tags);
	};
	localize::visitRawlog(observed, {{},
									 [&](const mrpt::obs::CSensoryFrame& sf) {
										 for (const auto& o : sf) take(o);
									 },
									 take});
	return out;
}

// Why tags in view were not seen. A tag is in view of a frame when the
// window's points cover its border square: per tag, the frames by the
// fraction of the square's cells (s / borderCells on a side) holding at
// least one point of its paper, seen / in view; and for the frames with at
// least half the cells covered but no sighting, by coverage, what became
// of the candidate nearest its centre ("not proposed": none within half
// the tag's size). A tag cut by the edge of the field of view, or between
// a rosette's petals, is not wholly in view however many points fall on
// its paper.
struct Coverage
{
	double cellsHit = 0;  // fraction of the border square's cells with a point
	double pointsPerCell = 0;  // points in the square per cell
};

Coverage tagCoverage(const sim::SimulationOutput& sim, size_t tag, size_t frame, size_t window)
{
	const size_t paper = sim.objectNames.size() - sim.truth.size() + tag;
	const TagFamilyInfo* fam = findFamily(sim.truth[tag].family);
	const int cells = fam ? fam->borderCells : 8;
	const double size = sim.truth[tag].size;
	std::vector<char> hit(static_cast<size_t>(cells * cells), 0);
	size_t inSquare = 0;
	for (size_t w = 0; w < window && w <= frame; w++)
	{
		const sim::FrameData& f = sim.frames[frame - w];
		const Eigen::Isometry3d toTag = truthInSensorFrame({sim.truth[tag]}, f)[0].pose.inverse();
		for (size_t i = f.firstPoint; i < f.firstPoint + f.pointCount; i++)
		{
			if (sim.points[i].object != static_cast<int32_t>(paper)) continue;
			const Eigen::Vector3d q = toTag * sim.points[i].local.cast<double>();
			const int cx = static_cast<int>(std::floor((q.x() / size + 0.5) * cells));
			const int cy = static_cast<int>(std::floor((q.y() / size + 0.5) * cells));
			if (cx < 0 || cy < 0 || cx >= cells || cy >= cells) continue;
			inSquare++;
			hit[static_cast<size_t>(cy * cells + cx)] = 1;
		}
	}
	const double n = static_cast<double>(hit.size());
	return {static_cast<double>(std::count(hit.begin(), hit.end(), 1)) / n, static_cast<double>(inSquare) / n};
}

void printMisses(const sim::SimulationOutput& sim, const localize::ObserveReport& report,
				 const std::vector<std::vector<TagDetection>>& seen, size_t window)
{
	const std::vector<double> bins = {0.01, 0.5, 0.9, 1.0};
	std::printf("\nper tag: frames by the fraction of its border square's cells holding a point, seen / frames; "
				"for frames at least half covered and not seen, the nearest candidate's verdict\n");
	std::map<std::string, size_t> allWhy;
	size_t fullFrames = 0, fullSeen = 0;
	for (size_t t = 0; t < sim.truth.size(); t++)
	{
		std::vector<size_t> frames(bins.size()), sighted(bins.size());
		std::map<std::string, size_t> why;
		std::vector<double> fullPerCell;
		for (size_t k = 0; k < seen.size() && k < sim.frames.size() && k < report.perScan.size(); k++)
		{
			const Coverage cov = tagCoverage(sim, t, k, window);
			if (cov.cellsHit < bins[0]) continue;
			const size_t bin =
				static_cast<size_t>(std::upper_bound(bins.begin(), bins.end(), cov.cellsHit) - bins.begin()) - 1;
			const TagDetection truth = truthInSensorFrame({sim.truth[t]}, sim.frames[k])[0];
			const bool found = std::any_of(seen[k].begin(), seen[k].end(), [&](const TagDetection& d) {
				return d.family == truth.family && d.id == truth.id;
			});
			frames[bin]++;
			sighted[bin] += found;
			if (bin + 1 == bins.size()) fullPerCell.push_back(cov.pointsPerCell);
			if (found || bin == 0) continue;  // under half covered: no tag to read
			const CandidateReport* nearest = nullptr;
			double best = 0.5 * truth.size;
			for (const CandidateReport& c : report.perScan[k].candidates)
			{
				const double d = (c.center - truth.position()).norm();
				if (d < best) best = d, nearest = &c;
			}
			const std::string range = bin + 1 == bins.size() ? "100%" : (bin == 1 ? "50-90%" : "90-99%");
			why[range + " " + (nearest ? verdictName(nearest->verdict) : "not proposed")]++;
		}
		std::printf("  %s:%d  cells hit", sim.truth[t].family.c_str(), sim.truth[t].id);
		for (size_t b = 0; b < bins.size(); b++)
			std::printf("  %s%.0f%% %zu/%zu", b + 1 < bins.size() ? ">=" : "", 100 * bins[b], sighted[b], frames[b]);
		std::printf("  (points per cell, median %.1f) | not seen:", quantile(fullPerCell, 0.5));
		for (const auto& [name, n] : why) std::printf(" %s %zu", name.c_str(), n), allWhy[name] += n;
		std::printf("\n");
		fullFrames += frames.back();
		fullSeen += sighted.back();
	}
	std::printf("every cell covered: %zu tag-frames, seen in %zu; at least half covered, not seen:", fullFrames, fullSeen);
	for (const auto& [name, n] : allWhy) std::printf(" %s %zu", name.c_str(), n);
	std::printf("\n");
}

void benchSensor(const SensorRun& s, const Options& opt)
{
	sim::Scene scene = sim::loadScene(TAGMAP_SOURCE_DIR "/share/scenes/localize_site.yaml", s.params);
	scene.runs.erase(std::remove_if(scene.runs.begin(), scene.runs.end(),
									[&](const sim::ScanRun& r) { return r.name != s.run; }),
					 scene.runs.end());
	sim::SimOptions simOpt;
	simOpt.seed = opt.seed;
	sim::SimulationOutput sim = sim::simulate(scene, simOpt);
	if (opt.scans > 0 && sim.frames.size() > opt.scans) sim.frames.resize(opt.scans);

	localize::ObserveParams observeParams;
	observeParams.window = opt.window ? opt.window : s.window;
	observeParams.maxWindow = opt.maxWindow;
	DetectionChoices choices;
	choices.configFile = opt.config;
	choices.families = opt.families;
	choices.threads = 1;
	PipelineParams params = resolveDetectionSettings(choices, localize::singleScanPipelineParams(observeParams.window));
	if (!opt.path.empty()) params.sensorView.enabled = opt.path == "sensor-view";
	localize::ObserveReport report;
	const mrpt::obs::CRawlog observed =
		localize::observeRawlog(sim::toRawlog(sim), Pipeline(params), observeParams, &report);
	const std::vector<std::vector<TagDetection>> seen = tagsPerScan(observed);

	std::vector<double> ms, points;
	std::map<std::string, std::vector<double>> stageMs, stageItems;
	std::vector<std::string> stageOrder;
	double totalSeconds = 0;
	std::map<std::string, size_t> verdicts;
	for (const localize::ScanTiming& t : report.perScan)
	{
		for (const CandidateReport& c : t.candidates) verdicts[verdictName(c.verdict)]++;
		ms.push_back(1000 * t.seconds);
		points.push_back(static_cast<double>(t.points));
		totalSeconds += t.seconds;
		for (const StageReport& st : t.stages)
		{
			if (!stageMs.count(st.name)) stageOrder.push_back(st.name);
			stageMs[st.name].push_back(1000 * st.seconds);
			stageItems[st.name].push_back(static_cast<double>(st.itemsIn));
		}
	}
	// Sightings' errors, all of them and, with --max-window, by the window
	// their detection ran on (the long one only where the short saw nothing).
	std::map<std::string, SightingErrors> errors;
	int sightings = 0, falseReports = 0, wrongId = 0, scansWithTag = 0;
	for (size_t k = 0; k < seen.size() && k < sim.frames.size(); k++)
	{
		const std::vector<TagDetection> truth = truthInSensorFrame(sim.truth, sim.frames[k]);
		const Evaluation ev = evaluateDetections(seen[k], truth);
		scansWithTag += !seen[k].empty();
		const bool longWindow = report.perScan[k].scansMerged > observeParams.window;
		for (size_t t = 0; t < ev.perTruth.size(); t++)
		{
			const TagError& e = ev.perTruth[t];
			if (!e.found) continue;
			sightings++;
			const TagDetection& d = seen[k][static_cast<size_t>(e.foundIndex)];
			errors["all sightings"].add(e, d, truth[t]);
			if (observeParams.maxWindow > observeParams.window)
				errors[longWindow ? "long window's" : "short window's"].add(e, d, truth[t]);
		}
		falseReports += ev.falsePositives();
		wrongId += ev.falseOf(FalseKind::WrongId);
	}

	// The pipeline runs on one thread, but OpenCV's own loops (ArUco's
	// thresholds and contours) use its thread pool on any CPU allowed.
	cpu_set_t allowed;
	const int cpus = sched_getaffinity(0, sizeof(allowed), &allowed) == 0 ? CPU_COUNT(&allowed) : 0;
	const std::string cores = cpus == 1 ? "one CPU allowed"
										: std::to_string(cpus) +
											  " CPUs allowed: OpenCV's pool may use them; taskset -c 0 for one core";
	std::printf("\n== %s, window %zu, %s: %zu scans, %.0f points per detection (median), families %s, 1 thread "
				"(%s)\n",
				s.label.c_str(), observeParams.window, params.sensorView.enabled ? "sensor view" : "map path",
				report.perScan.size(), quantile(points, 0.5), opt.families.c_str(), cores.c_str());
	std::printf("detect ms per scan: median %.2f, p90 %.2f, max %.2f; %.1f scans/s (all scans)\n", quantile(ms, 0.5),
				quantile(ms, 0.9), quantile(ms, 1.0), report.perScan.size() / std::max(totalSeconds, 1e-9));
	std::printf("%-20s %10s %10s %10s\n", "stage", "median ms", "p90 ms", "items in");
	for (const std::string& name : stageOrder)
		std::printf("%-20s %10.3f %10.3f %10.0f\n", name.c_str(), quantile(stageMs[name], 0.5),
					quantile(stageMs[name], 0.9), quantile(stageItems[name], 0.5));
	std::printf("candidates (all scans):");
	for (const auto& [name, n] : verdicts) std::printf(" %s %zu", name.c_str(), n);
	std::printf("\n");
	std::printf("scans with a tag %d of %zu, sightings %d, false %d (wrong id %d)\n", scansWithTag, seen.size(),
				sightings, falseReports, wrongId);
	for (const auto& [label, e] : errors) e.print(label);
	if (opt.misses) printMisses(sim, report, seen, observeParams.window);
}

[[noreturn]] void usage(const char* why)
{
	std::fprintf(stderr,
				 "tagmap-bench-observe: %s\nUsage: tagmap-bench-observe [--sensor spinning|spinning128|spinning32|spinning16|livox|both] [--scans N] "
				 "[--family LIST] [--seed S] [--window N] [--max-window M] [--misses] [--sensor-view | --map-path] [--config FILE]\n",
				 why);
	std::exit(2);
}
}  // namespace

int main(int argc, char** argv)
{
	Options opt;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		if (a == "--misses")
		{
			opt.misses = true;
			continue;
		}
		if (a == "--sensor-view" || a == "--map-path")
		{
			if (!opt.path.empty() && opt.path != a.substr(2)) usage("--sensor-view or --map-path, not both");
			opt.path = a.substr(2);
			continue;
		}
		if (i + 1 >= argc) usage(("missing value after " + a).c_str());
		const std::string v = argv[++i];
		if (a == "--sensor" && (v == "spinning" || v == "spinning128" || v == "spinning32" || v == "spinning16" || v == "livox" || v == "both")) opt.sensor = v;
		else if (a == "--scans") opt.scans = std::strtoul(v.c_str(), nullptr, 10);
		else if (a == "--family") opt.families = v;
		else if (a == "--window" && std::strtoul(v.c_str(), nullptr, 10) > 0)
			opt.window = std::strtoul(v.c_str(), nullptr, 10);
		else if (a == "--max-window" && std::strtoul(v.c_str(), nullptr, 10) > 1)
			opt.maxWindow = std::strtoul(v.c_str(), nullptr, 10);
		else if (a == "--seed") opt.seed = std::strtoull(v.c_str(), nullptr, 10);
		else if (a == "--config") opt.config = v;
		else usage(("unknown option or value: " + a + " " + v).c_str());
	}
	try
	{
		localize::keepScanMemoryForReuse();  // as `tagmap observe` does
		const std::map<std::string, SensorRun> runs = {
			{"spinning", {"spinning 64 x 512, 10 Hz", "robot", {{"robot_beams", 64}, {"robot_columns", 512}}, 1}},
			{"spinning128", {"spinning 128 x 1024, 10 Hz", "robot", {}, 1}},
			// Sparse rows: each beam's row lies several view pixels from the next (the sensor view's hardest case)
			{"spinning32", {"spinning 32 x 1024, 10 Hz", "robot", {{"robot_beams", 32}, {"robot_columns", 1024}}, 1}},
			{"spinning16", {"spinning 16 x 1024, 10 Hz", "robot", {{"robot_beams", 16}, {"robot_columns", 1024}}, 1}},
			{"livox", {"livox 0.1 s frames", "robot_livox", {}, 3}},
		};
		for (const std::string name : {"spinning", "spinning128", "spinning32", "spinning16", "livox"})
			if (opt.sensor == name || (opt.sensor == "both" && (name == "spinning" || name == "livox")))
				benchSensor(runs.at(name), opt);
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "tagmap-bench-observe: %s\n", e.what());
		return 1;
	}
	return 0;
}
