#include "ray_engine.h"

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include "tagmap/sim/beam_footprint.h"
#include "tagmap/sim/intensity_model.h"
#include "tagmap/sim/pointing_jitter.h"
#include "tagmap/sim/range_noise.h"
#include "tagmap/sim/rng.h"
#include "tagmap/sim/scan_pattern.h"

namespace tagmap::sim
{
namespace
{
struct Block
{
	size_t frame, begin, end;
};

struct SensorModels
{
	std::unique_ptr<ScanPattern> pattern;
	std::unique_ptr<IntensityModel> intensity;
	std::unique_ptr<BeamFootprint> footprint;
	std::unique_ptr<RangeNoise> noise;
	std::unique_ptr<PointingJitter> jitter;
};

void castBlock(const Block& b, const Frame& f, const ScanRun& run, const SensorSpec& spec, const SensorModels& m,
			   const World& world, uint64_t seed, std::vector<SimPoint>& out)
{
	Rng rng(streamSeed(seed, kStreamRays, b.frame, b.begin));
	const Eigen::Isometry3d refInv = f.truePose.inverse();
	Eigen::Vector3d dirS;
	double dt = 0;
	Echo echo;
	for (size_t i = b.begin; i < b.end; i++)
	{
		m.pattern->ray(f.clock, i, dirS, dt);
		const Eigen::Isometry3d T = f.moving ? sensorPoseAt(run, f.t0 + dt) : f.truePose;
		const Eigen::Vector3d o = T.translation();
		const Eigen::Vector3d d = T.linear() * dirS;  // as the encoders report it
		const Eigen::Vector3d beam = m.jitter->apply(d, rng);  // where the pulse really goes
		if (!m.footprint->measure(world, o, beam, T.linear().col(2), spec.minRange, spec.maxRange, echo)) continue;
		const double r = m.noise->apply(echo.range, m.intensity->amplitude(echo.strength, echo.range), rng);
		SimPoint p;
		Eigen::Vector3d local = refInv * (o + r * d);  // perfectly deskewed
		if (f.moving && run.deskewResidual > 0)
			local += run.deskewResidual * (r * dirS - local);  // part of the motion left uncompensated
		p.local = local.cast<float>();
		p.intensity01 = static_cast<float>(m.intensity->intensity(echo.strength, echo.range, rng));
		p.object = echo.object;
		out.push_back(p);
	}
}
}  // namespace

EngineResult castFrames(const Scene& scene, const World& world, const std::vector<Frame>& frames,
						const SimOptions& options, const CountProgressFn& progress)
{
	std::vector<SensorModels> models(scene.sensors.size());
	for (size_t s = 0; s < scene.sensors.size(); s++)
	{
		const SensorSpec& spec = scene.sensors[s];
		models[s].pattern = makeScanPattern(spec);
		models[s].intensity = std::make_unique<IntensityModel>(spec.intensity);
		models[s].footprint = std::make_unique<BeamFootprint>(spec.beam, *models[s].intensity);
		models[s].noise = std::make_unique<RangeNoise>(spec.rangeNoiseSigma, spec.rangeWalk);
		models[s].jitter = std::make_unique<PointingJitter>(spec.beam.pointingJitterMrad);
	}

	EngineResult res;
	std::vector<Block> blocks;
	const size_t blockRays = std::max<size_t>(1, options.blockRays);
	for (size_t fi = 0; fi < frames.size(); fi++)
	{
		res.rays += frames[fi].rays;
		for (size_t b = 0; b < frames[fi].rays; b += blockRays)
			blocks.push_back({fi, b, std::min(frames[fi].rays, b + blockRays)});
	}

	std::vector<std::vector<SimPoint>> outs(blocks.size());
	std::atomic<size_t> next{0};
	std::mutex progressMutex;  // one report at a time, counts never step back
	size_t raysDone = 0;
	auto worker = [&]() {
		for (size_t k = next++; k < blocks.size(); k = next++)
		{
			const Block& b = blocks[k];
			const Frame& f = frames[b.frame];
			outs[k].reserve(b.end - b.begin);
			castBlock(b, f, scene.runs[f.run], scene.sensors[f.sensor], models[f.sensor], world, options.seed,
					  outs[k]);
			outs[k].shrink_to_fit();
			if (progress)
			{
				std::lock_guard<std::mutex> lock(progressMutex);
				raysDone += b.end - b.begin;
				progress(raysDone, res.rays);
			}
		}
	};
	unsigned nThreads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
	nThreads = static_cast<unsigned>(std::min<size_t>(nThreads, std::max<size_t>(1, blocks.size())));
	std::vector<std::thread> pool;
	for (unsigned t = 1; t < nThreads; t++) pool.emplace_back(worker);
	worker();
	for (auto& t : pool) t.join();

	size_t total = 0;
	for (const auto& o : outs) total += o.size();
	res.points.reserve(total);
	res.frameCounts.assign(frames.size(), 0);
	for (size_t k = 0; k < blocks.size(); k++)
	{
		res.frameCounts[blocks[k].frame] += outs[k].size();
		res.points.insert(res.points.end(), outs[k].begin(), outs[k].end());
		std::vector<SimPoint>().swap(outs[k]);
	}
	return res;
}

}  // namespace tagmap::sim
