// Casting all frames' rays on worker threads. Work is cut into fixed blocks
// of rays, each with its own random stream (seed, frame, block), and results
// are concatenated in block order: identical output for any thread count.
#pragma once

#include <vector>

#include "tagmap/sim/scene.h"
#include "tagmap/sim/simulate.h"
#include "tagmap/sim/trajectory.h"
#include "tagmap/sim/world.h"

namespace tagmap::sim
{
struct EngineResult
{
	std::vector<SimPoint> points;  // grouped by frame, frame-local
	std::vector<size_t> frameCounts;  // points per frame
	size_t rays = 0;
};

EngineResult castFrames(const Scene& scene, const World& world, const std::vector<Frame>& frames,
						const SimOptions& options, const CountProgressFn& progress = {});

}  // namespace tagmap::sim
