#include "tagmap/sim/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ray_engine.h"
#include "tagmap/errors.h"
#include "tagmap/tag_family.h"
#include "tagmap/sim/drift.h"
#include "tagmap/sim/point_budget.h"
#include "tagmap/sim/tag_paper.h"
#include "tagmap/sim/trajectory.h"

namespace tagmap::sim
{
namespace
{
size_t totalRays(const std::vector<Frame>& frames)
{
	size_t n = 0;
	for (const auto& f : frames) n += f.rays;
	return n;
}

// Billions of rays (a tiny step_deg, a huge --points) would only end in
// bad_alloc or run for days: refuse them up front, naming the scene.
void checkRayBudget(const Scene& scene, const std::vector<Frame>& frames)
{
	constexpr double kMaxRays = 2e9;
	double rays = 0;  // in double: a pattern's count may be absurd, the sum must not wrap
	for (const auto& f : frames) rays += static_cast<double>(f.rays);
	if (rays > kMaxRays)
		throw InputError(scene.file.empty() ? scene.name : scene.file, "sensors",
						 "the scene needs " + std::to_string(rays) +
							 " rays, more than 2e9: use coarser steps, shorter runs or a smaller --points");
}

// Rays of a cheap pilot run used to measure the fraction of rays that return.
constexpr double kPilotRays = 300000;

/** Factor that makes `scene` produce about `target` points. */
double densityForTarget(const Scene& scene, const World& world, size_t target, const SimOptions& options)
{
	const auto full = scheduleFrames(scene);
	checkRayBudget(scene, full);
	const size_t rays = totalRays(full);
	if (rays == 0) return 1;
	Scene pilot = scene;
	const double pilotFactor = std::min(1.0, kPilotRays / static_cast<double>(rays));
	scaleSceneDensity(pilot, pilotFactor);
	const auto frames = scheduleFrames(pilot);
	const EngineResult r = castFrames(pilot, world, frames, options);
	const double hitFraction = r.rays ? static_cast<double>(r.points.size()) / static_cast<double>(r.rays) : 0;
	if (hitFraction <= 0) return 1;
	return static_cast<double>(target) / hitFraction / static_cast<double>(rays);
}
// The frame contributing most points to each tag decides where the map shows it.
std::vector<TagDetection> truthAsMapped(const SimulationOutput& out, size_t firstTagObject)
{
	std::vector<TagDetection> mapped = out.truth;
	std::vector<size_t> best(out.truth.size(), 0), bestFrame(out.truth.size(), 0);
	for (size_t k = 0; k < out.frames.size(); k++)
	{
		std::vector<size_t> count(out.truth.size(), 0);
		const FrameData& fd = out.frames[k];
		for (size_t i = fd.firstPoint; i < fd.firstPoint + fd.pointCount; i++)
		{
			const int32_t o = out.points[i].object;
			if (o >= static_cast<int32_t>(firstTagObject)) count[o - firstTagObject]++;
		}
		for (size_t t = 0; t < count.size(); t++)
			if (count[t] > best[t])
			{
				best[t] = count[t];
				bestFrame[t] = k;
			}
	}
	for (size_t t = 0; t < mapped.size(); t++)
	{
		if (out.frames.empty()) break;
		const FrameData& fd = out.frames[bestFrame[t]];
		mapped[t].pose = fd.driftedPose * fd.truePose.inverse() * out.truth[t].pose;
		mapped[t].corners = cornersFromPose(mapped[t].pose, mapped[t].size);
	}
	return mapped;
}

std::vector<TagSighting> tagSightings(const SimulationOutput& out, size_t firstTagObject)
{
	std::vector<TagSighting> seen(out.truth.size());
	std::vector<double> cosMax(out.truth.size(), 0);
	for (const FrameData& fd : out.frames)
	{
		std::vector<bool> inFrame(out.truth.size(), false);
		for (size_t i = fd.firstPoint; i < fd.firstPoint + fd.pointCount; i++)
		{
			const SimPoint& p = out.points[i];
			if (p.object < static_cast<int32_t>(firstTagObject)) continue;
			const size_t t = static_cast<size_t>(p.object) - firstTagObject;
			const TagDetection& tag = out.truth[t];
			TagSighting& s = seen[t];
			const double range = p.local.cast<double>().norm();
			s.rangeMin = s.points ? std::min(s.rangeMin, range) : range;
			s.rangeMax = std::max(s.rangeMax, range);
			s.points++;
			inFrame[t] = true;
			const Eigen::Vector3d world = fd.truePose * p.local.cast<double>();
			const Eigen::Vector3d inTag = tag.pose.inverse() * world;
			if (std::abs(inTag.x()) <= 0.5 * tag.size && std::abs(inTag.y()) <= 0.5 * tag.size) s.pointsInSquare++;
			const Eigen::Vector3d ray = fd.truePose.linear() * p.local.cast<double>().normalized();
			cosMax[t] = std::max(cosMax[t], std::abs(ray.dot(tag.pose.linear().col(2))));
		}
		for (size_t t = 0; t < seen.size(); t++) seen[t].scans += inFrame[t];
	}
	for (size_t t = 0; t < seen.size(); t++)
	{
		const TagFamilyInfo* family = findFamily(out.truth[t].family);
		const int cells = family ? family->borderCells : 0;
		if (cells > 0) seen[t].pointsPerCell = static_cast<double>(seen[t].pointsInSquare) / (cells * cells);
		if (seen[t].points) seen[t].incidenceDegMin = std::acos(std::min(1.0, cosMax[t])) * 180 / M_PI;
	}
	return seen;
}
}  // namespace

SimulationOutput simulate(const Scene& sceneIn, const SimOptions& options, const CountProgressFn& progress)
{
	const auto start = std::chrono::steady_clock::now();
	SimulationOutput out;
	out.sceneName = sceneIn.name;
	out.intensityScale = options.intensityScale;

	// The world: scene objects plus one paper per tag, at its seed-jittered pose.
	std::vector<SceneObject> objects = sceneIn.objects;
	for (size_t ti = 0; ti < sceneIn.tags.size(); ti++)
	{
		const TagSpec& spec = sceneIn.tags[ti];
		const Eigen::Isometry3d printed = printedTagPose(spec, options.seed, ti);
		SceneObject paper = makeTagPaper(spec, printed);
		paper.tagIndex = static_cast<int>(ti);
		objects.push_back(std::move(paper));
		out.truth.push_back(tagTruth(spec, printed));
	}
	for (const auto& o : objects) out.objectNames.push_back(o.name);
	const World world(objects);

	Scene scene = sceneIn;
	if (options.targetPoints > 0)
	{
		out.densityFactor = densityForTarget(scene, world, options.targetPoints, options);
		scaleSceneDensity(scene, out.densityFactor);
	}
	for (const auto& s : scene.sensors) out.sensorNames.push_back(s.name);

	const std::vector<Frame> frames = scheduleFrames(scene);
	checkRayBudget(scene, frames);
	EngineResult cast = castFrames(scene, world, frames, options, progress);
	out.raysCast = cast.rays;
	out.points = std::move(cast.points);

	// Poses a SLAM system would have used to merge the frames.
	std::vector<DriftStep> steps(frames.size());
	for (size_t k = 0; k < frames.size(); k++)
	{
		steps[k].truePose = frames[k].truePose;
		const ScanRun& run = scene.runs[frames[k].run];
		steps[k].scale = run.driftScale;
		steps[k].scaleError = run.odometryScaleError;
		steps[k].headingBiasRadPerM = run.odometryHeadingBiasDegPerM * M_PI / 180;
		steps[k].mount = run.mount;
		// Sensor-clock time between the frames' reference instants.
		const auto mid = [&](size_t j) { return frames[j].clock + 0.5 * frames[j].duration; };
		steps[k].seconds = k ? std::max(0.0, mid(k) - mid(k - 1)) : 0.0;
	}
	const auto drifted = driftPoses(steps, scene.drift, options.seed);

	size_t first = 0;
	for (size_t k = 0; k < frames.size(); k++)
	{
		FrameData fd;
		fd.run = frames[k].run;
		fd.runName = scene.runs[frames[k].run].name;
		fd.sensorName = scene.sensors[frames[k].sensor].name;
		fd.time = frames[k].tRef;
		fd.stamp = frames[k].clock + 0.5 * frames[k].duration;
		fd.duration = frames[k].duration;
		fd.truePose = frames[k].truePose;
		fd.driftedPose = drifted[k];
		fd.mount = scene.runs[frames[k].run].mount;
		fd.firstPoint = first;
		fd.pointCount = cast.frameCounts[k];
		first += fd.pointCount;
		out.frames.push_back(fd);
	}

	// Merge at the drifted poses.
	const size_t firstTagObject = sceneIn.objects.size();
	out.map.resize(out.points.size());
	for (const FrameData& fd : out.frames)
	{
		const Eigen::Isometry3f T = fd.driftedPose.cast<float>();
		for (size_t i = fd.firstPoint; i < fd.firstPoint + fd.pointCount; i++)
		{
			const SimPoint& p = out.points[i];
			const Eigen::Vector3f g = T * p.local;
			out.map.setPointFast(i, g.x(), g.y(), g.z());
			out.map.setPointIntensity(i, static_cast<float>(p.intensity01 * options.intensityScale));
		}
	}
	out.map.mark_as_modified();
	out.tagSightings = tagSightings(out, firstTagObject);
	out.truthInMap = truthAsMapped(out, firstTagObject);
	out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return out;
}

}  // namespace tagmap::sim
