#include "tagmap/pipeline.h"

#include <chrono>
#include <mutex>
#include <optional>
#include <type_traits>

#include "candidate.h"
#include "candidate_decoder.h"
#include "candidate_proposals.h"
#include "map_view.h"
#include "tagmap/derived_lengths.h"
#include "tagmap/intensity_gradient.h"
#include "tagmap/merge_detections.h"
#include "tagmap/octree_gather.h"
#include "tagmap/parallel.h"
#include "tagmap/point_spacing.h"
#include "tagmap/read_evidence.h"
#include "tagmap/sensor_view.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/surface_noise.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/voxel_grid.h"

namespace tagmap
{
namespace
{
using namespace detail;
using Clock = std::chrono::steady_clock;

/** Fewer points than this: no map to look for tags in. */
constexpr size_t kMinMapPoints = 16;

// What a stage reports as its items out (Detections::stages), by what it returns.
size_t itemsOut(double /*spacing*/) { return 1; }
size_t itemsOut(size_t count) { return count; }
size_t itemsOut(const VoxelGrid& grid) { return grid.voxelCount(); }
size_t itemsOut(const IntensityGradientResult& r) { return r.keptPoints.size(); }
size_t itemsOut(const std::unique_ptr<const OctreeGatherer>& g) { return g->occupiedLeaves(); }
size_t itemsOut(const SensorViewReads& r) { return r.reads.size(); }
size_t itemsOut(const PointsSubset& s) { return s.xs.size(); }
template <typename T>
size_t itemsOut(const std::vector<T>& v)
{
	return v.size();
}

// Every stage's bookkeeping, the same for all: its row in Detections::stages
// (seconds, items in, items out) and its progress. A stage shows (0, 1) when
// it starts and (1, 1) when it ends; work counted as it goes (points,
// candidates) shows (0, n), then the counts its worker threads report, in
// increasing order, and (n, n) at the end.
class StageRunner
{
   public:
	StageRunner(std::vector<StageReport>& stages, const ProgressFn& progress) : stages_(stages), progress_(progress) {}

	/** Runs `work()` as stage `name` on `itemsIn` items and returns its
	 *  result; `work(const CountProgressFn&)` is counted work over itemsIn. */
	template <typename Work>
	auto run(const std::string& name, size_t itemsIn, Work&& work)
	{
		constexpr bool counted = std::is_invocable_v<Work, const CountProgressFn&>;
		const size_t total = counted ? itemsIn : 1;
		size_t shown = 0;
		std::mutex mutex;  // the workers report; the printer is single-threaded and counts only go up
		const CountProgressFn count = [&](size_t done, size_t all) {
			std::lock_guard<std::mutex> lock(mutex);
			if (done <= shown) return;
			shown = done;
			show(name, done, all);
		};
		show(name, 0, total);
		const auto t0 = Clock::now();
		auto result = [&] {
			if constexpr (counted) return work(count);
			else return work();
		}();
		stages_.push_back({name, std::chrono::duration<double>(Clock::now() - t0).count(), itemsIn, itemsOut(result)});
		if (shown < total) show(name, total, total);
		return result;
	}

   private:
	void show(const std::string& name, size_t done, size_t total) const
	{
		if (progress_) progress_(name, done, total);
	}
	std::vector<StageReport>& stages_;
	const ProgressFn& progress_;
};

// Stages 1-3 of the paper on a map: points of high intensity gradient,
// their clusters (at several tolerances and density levels, oversized ones
// split), the boxes that may hold a tag.
std::vector<Candidate> proposeFromGradient(StageRunner& stage, const MapView& m, const VoxelGrid& grid,
										   const DerivedLengths& len, const PipelineParams& p, unsigned threads,
										   std::vector<CandidateReport>& reports)
{
	IntensityGradientResult edges = stage.run("intensity_gradient", m.n, [&](const CountProgressFn& count) {
		return filterByIntensityGradient(m.xs, m.ys, m.zs, m.is, grid, len.gradientRadius, p.gradient, threads, 0,
										 count);
	});
	std::vector<Cluster> clusters;
	stage.run("clustering", edges.keptPoints.size(), [&] {
		return addClusters(m, edges.keptPoints, 1.0, len.spacing, p.clustering, clusters);
	});
	stage.run("cluster_split", edges.keptPoints.size(), [&] {
		return splitClusters(m, edges, len, p, clusters);
	});
	stage.run("sparse_levels", edges.sparsePoints.size(), [&] {
		return clusterSparseLevels(m, std::move(edges), len, p, threads, clusters);
	});
	return stage.run("candidate_filter", clusters.size(), [&] {
		return proposeCandidates(m, clusters, filterParams(p), len, reports);
	});
}

// The worker's own decoder, built on first use with the families asked for.
template <typename Decoder, typename Params>
Decoder& perWorker(std::vector<std::unique_ptr<Decoder>>& pool, std::mutex& mutex, unsigned worker,
				   const std::vector<std::string>& families, const Params& params)
{
	std::lock_guard<std::mutex> lock(mutex);
	if (pool.size() <= worker) pool.resize(worker + 1);
	if (!pool[worker]) pool[worker] = std::make_unique<Decoder>(families, params);
	return *pool[worker];
}

}  // namespace

Pipeline::Pipeline(PipelineParams params) : params_(std::move(params))
{
	params_.validate();
	decodedFamilies_ = acceptableFamilies(familiesAsked(params_), readOrientations(params_), params_.evidence);
}

CandidateDecoders Pipeline::decodersFor(unsigned worker) const
{
	return {perWorker(decoders_, decodersMutex_, worker, decodedFamilies_, params_.decoder),
			perWorker(softDecoders_, decodersMutex_, worker, decodedFamilies_, params_.softDecoder)};
}

const TagDecoder& Pipeline::viewDecoder() const
{
	// The sensor sees a tag's printed face, never its back: the view is read
	// unmirrored only, its quads searched at its own decimation.
	TagDecoderParams unmirrored = params_.decoder;
	unmirrored.tryMirrored = false;
	unmirrored.quadDecimate = static_cast<float>(params_.sensorView.quadDecimate);
	return perWorker(viewDecoders_, decodersMutex_, 0, decodedFamilies_, unmirrored);
}

Detections Pipeline::detect(const mrpt::maps::CPointsMapXYZI& map, const ProgressFn& progress, bool keepImages) const
{
	return detect(map, {}, progress, keepImages);
}

Detections Pipeline::detect(const mrpt::maps::CPointsMapXYZI& map, const std::vector<Eigen::Vector3d>& viewpoints,
							const ProgressFn& progress, bool keepImages) const
{
	const auto tStart = Clock::now();
	Detections out;
	const MapView whole(map);
	if (whole.n < kMinMapPoints) return out;
	const unsigned threads = resolveThreads(params_.threads);
	StageRunner stage(out.stages, progress);

	// A scan read from its own sensor first: where the view holds no read,
	// there is nothing to measure the scan's lengths for; where it holds
	// some, only the points around them are measured and searched.
	MapView m = whole;
	std::optional<SensorViewReads> viewReads;
	std::optional<PointsSubset> nearReads;
	if (params_.sensorView.enabled)
	{
		viewReads = stage.run("sensor_view", m.n, [&] {
			return readSensorView(m, params_, decodedFamilies_, viewDecoder(), decodersFor(0).soft);
		});
		if (viewReads->reads.empty())
		{
			out.totalSeconds = std::chrono::duration<double>(Clock::now() - tStart).count();
			return out;
		}
		nearReads = stage.run("near_reads", m.n, [&] {
			return PointsSubset(whole, pointsNearReads(viewReads->view, viewReads->reads, params_.sensorView.nearSides));
		});
		m = nearReads->view();
	}
	const double spacing = stage.run("point_spacing", m.n, [&] {
		return estimatePointSpacing(m.xs, m.ys, m.zs, m.n, params_.spacing, threads);
	});
	out.pointSpacing = spacing;
	if (!(spacing > 0)) return out;
	DerivedLengths len = DerivedLengths::of(spacing, params_);
	const VoxelGrid grid = stage.run("neighbour_index", m.n, [&] {
		return VoxelGrid(m.xs, m.ys, m.zs, m.n, len.voxelCell, threads);
	});
	out.surfaceNoise = stage.run("surface_noise", m.n, [&] { return estimateSurfaceNoise(m.xs, m.ys, m.zs, m.n, grid); });
	len.setSurfaceNoise(out.surfaceNoise);
	std::vector<Candidate> candidates;
	if (viewReads)
		candidates = stage.run("view_candidates", viewReads->reads.size(), [&] {
			return proposeFromSensorView(whole, *viewReads, nearReads->indices, params_, len, out.candidates);
		});
	else
		candidates = proposeFromGradient(stage, m, grid, len, params_, threads, out.candidates);
	const auto gatherer = stage.run("octree", grid.voxelCount(), [&] {
		return std::make_unique<const OctreeGatherer>(grid, len.octreeLeaf, params_.gather, threads);
	});
	std::vector<TagDetection> found = stage.run("decode", candidates.size(), [&](const CountProgressFn& count) {
		return decodeCandidates(params_, m, grid, *gatherer, viewpoints, len, decodedFamilies_, keepImages, candidates,
								out.candidates, threads, count, [this](unsigned worker) { return decodersFor(worker); });
	});
	out.tags = stage.run("merge", found.size(), [&] { return mergeDetections(std::move(found), params_.merge); });
	out.totalSeconds = std::chrono::duration<double>(Clock::now() - tStart).count();
	return out;
}

}  // namespace tagmap
