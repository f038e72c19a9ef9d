#include "tagmap/pipeline.h"

#include <algorithm>
#include <chrono>
#include <mutex>

#include "tagmap/candidate_filter.h"
#include "tagmap/clustering.h"
#include "tagmap/intensity_gradient.h"
#include "tagmap/image_variants.h"
#include "tagmap/intermediate_plane.h"
#include "tagmap/merge_detections.h"
#include "tagmap/octree_gather.h"
#include "tagmap/parallel.h"
#include "tagmap/pattern_refinement.h"
#include "tagmap/point_spacing.h"
#include "tagmap/read_evidence.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/support_plane.h"
#include "tagmap/surface_noise.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_family.h"
#include "tagmap/tag_pose.h"
#include "tagmap/voxel_grid.h"

namespace tagmap
{
namespace
{
using Clock = std::chrono::steady_clock;

/** How far a decoded square's edge may be from --tag-size: corners on a
 *  blurred image are a pixel or two off, a code read into a pattern twice
 *  or half the size is no tag. */
constexpr double kGivenSizeTolerance = 0.3;

class StageTimer
{
   public:
	StageTimer(Detections& d, std::string name, size_t in) : d_(d), t0_(Clock::now())
	{
		d_.stages.push_back({std::move(name), 0, in, 0});
	}
	void done(size_t out)
	{
		d_.stages.back().itemsOut = out;
		d_.stages.back().seconds = std::chrono::duration<double>(Clock::now() - t0_).count();
	}

   private:
	Detections& d_;
	Clock::time_point t0_;
};

// Everything one candidate needs from the map, in one place.
struct MapView
{
	const float *xs, *ys, *zs, *is;
	size_t n;
};

}  // namespace

Pipeline::Pipeline(PipelineParams params) : params_(std::move(params)) { params_.validate(); }

namespace
{
// The worker's own decoder, built on first use with the families asked for.
template <typename Decoder, typename Params>
Decoder& perWorker(std::vector<std::unique_ptr<Decoder>>& pool, std::mutex& mutex, unsigned worker,
				   const std::vector<std::string>& families, const Params& params)
{
	std::lock_guard<std::mutex> lock(mutex);
	if (pool.size() <= worker) pool.resize(worker + 1);
	if (!pool[worker]) pool[worker] = std::make_unique<Decoder>(families.empty() ? parseFamilyList("") : families, params);
	return *pool[worker];
}
}  // namespace

SoftTagDecoder& Pipeline::softDecoderFor(unsigned worker) const
{
	return perWorker(softDecoders_, decodersMutex_, worker, params_.families, params_.softDecoder);
}

TagDecoder& Pipeline::decoderFor(unsigned worker) const
{
	return perWorker(decoders_, decodersMutex_, worker, params_.families, params_.decoder);
}

Detections Pipeline::detect(const mrpt::maps::CPointsMapXYZI& map, const ProgressFn& progress, bool keepImages) const
{
	const auto tStart = Clock::now();
	Detections out;
	const MapView m{map.getPointsBufferRef_x().data(), map.getPointsBufferRef_y().data(),
					map.getPointsBufferRef_z().data(), map.getPointsBufferRef_intensity().data(), map.size()};
	const unsigned threads = resolveThreads(params_.threads);
	auto report = [&](const std::string& stage, size_t done, size_t total) {
		if (progress) progress(stage, done, total);
	};
	if (m.n < 16) return out;

	StageTimer tSpacing(out, "point_spacing", m.n);
	const double spacing = estimatePointSpacing(m.xs, m.ys, m.zs, m.n, params_.spacing, threads);
	tSpacing.done(1);
	out.pointSpacing = spacing;
	if (!(spacing > 0)) return out;
	const double radius = params_.gradientRadiusSpacings * spacing;

	report("neighbour_index", 0, 1);
	StageTimer tGrid(out, "neighbour_index", m.n);
	const VoxelGrid grid(m.xs, m.ys, m.zs, m.n, radius, threads);
	tGrid.done(grid.voxelCount());
	report("neighbour_index", 1, 1);

	StageTimer tNoise(out, "surface_noise", m.n);
	const double surfaceNoise = estimateSurfaceNoise(m.xs, m.ys, m.zs, m.n, grid);
	tNoise.done(1);
	out.surfaceNoise = surfaceNoise;
	// How far a flat surface's points may stray from its plane: the measured
	// noise (3 sigma), at least two spacings (a noiseless map's own sampling).
	const double planeNoise = std::max(2 * spacing, 3 * surfaceNoise);

	// Clusters at several tolerances: the point spacing varies across a map
	// (near and far views, overlapping passes), and a tag scanned more
	// sparsely than the map's median breaks into fragments at the finest
	// tolerance. A coarser one re-joins it; identical clusters are kept once.
	std::vector<Cluster> clusters;
	auto addClusters = [&](const std::vector<uint32_t>& kept, double levelScale) {
		for (double scale : params_.clustering.scales)
			for (Cluster& c : clusterPoints(m.xs, m.ys, m.zs, kept,
											levelScale * scale * params_.clustering.toleranceSpacings * spacing,
											params_.clustering.minPoints))
			{
				const bool seen = std::any_of(clusters.begin(), clusters.end(), [&](const Cluster& o) {
					return o.points.size() == c.points.size() && o.points.front() == c.points.front();
				});
				if (!seen) clusters.push_back(std::move(c));
			}
	};

	report("intensity_gradient", 0, m.n);
	StageTimer tGradient(out, "intensity_gradient", m.n);
	// The workers report; the printer is single-threaded and counts only go up.
	std::mutex gradientProgressMutex;
	size_t gradientShown = 0;
	IntensityGradientResult level =
		filterByIntensityGradient(m.xs, m.ys, m.zs, m.is, grid, params_.gradient, threads, 0, [&](size_t done, size_t total) {
			std::lock_guard<std::mutex> lock(gradientProgressMutex);
			if (done <= gradientShown) return;
			gradientShown = done;
			report("intensity_gradient", done, total);
		});
	tGradient.done(level.keptPoints.size());
	if (gradientShown < m.n) report("intensity_gradient", m.n, m.n);

	report("clustering", 0, 1);
	StageTimer tCluster(out, "clustering", level.keptPoints.size());
	addClusters(level.keptPoints, 1.0);
	tCluster.done(clusters.size());
	report("clustering", 1, 1);

	// Density levels: where the map is sparser than its median (far from the
	// sensor, a fast pass), a point has too few neighbours within r to fit a
	// gradient. Those points alone are run again at 3x the radius and
	// clustered at 3x the tolerance, and so on, so the result follows the
	// local spacing, not the map's densest part.
	StageTimer tSparse(out, "sparse_levels", level.sparsePoints.size());
	size_t sparseKept = 0;
	double levelScale = 1;
	for (int l = 1; l < params_.gradient.densityLevels && level.sparsePoints.size() >= params_.clustering.minPoints; l++)
	{
		levelScale *= 3;
		const std::vector<uint32_t> subset = std::move(level.sparsePoints);
		std::vector<float> sx(subset.size()), sy(subset.size()), sz(subset.size()), si(subset.size());
		for (size_t k = 0; k < subset.size(); k++)
			sx[k] = m.xs[subset[k]], sy[k] = m.ys[subset[k]], sz[k] = m.zs[subset[k]], si[k] = m.is[subset[k]];
		const VoxelGrid subGrid(sx.data(), sy.data(), sz.data(), subset.size(), levelScale * radius, threads);
		level = filterByIntensityGradient(sx.data(), sy.data(), sz.data(), si.data(), subGrid, params_.gradient, threads,
										  level.intensitySpread);
		for (auto* v : {&level.keptPoints, &level.sparsePoints})
			for (auto& k : *v) k = subset[k];  // back to map indices (still ascending)
		sparseKept += level.keptPoints.size();
		addClusters(level.keptPoints, levelScale);
	}
	tSparse.done(sparseKept);

	StageTimer tFilter(out, "candidate_filter", clusters.size());
	CandidateFilterParams cf = params_.candidates;
	if (params_.tagSize > 0) cf.tagSize = params_.tagSize;
	// A candidate: the box to gather around, and the report it fills in.
	struct Candidate
	{
		size_t report;
		OrientedBox box;
	};
	std::vector<Candidate> candidates;
	for (size_t c = 0; c < clusters.size(); c++)
	{
		const std::string why = rejectCandidate(clusters[c].box, radius, planeNoise, cf);
		CandidateReport rep;
		rep.center = clusters[c].box.center;
		rep.extent = clusters[c].box.extent;
		rep.clusterPoints = clusters[c].points.size();
		rep.verdict = why.empty() ? "candidate" : why;
		out.candidates.push_back(rep);
		if (why.empty()) candidates.push_back({out.candidates.size() - 1, clusters[c].box});
		if (why != "squareness") continue;
		// Too long for a tag: maybe a tag clustered together with an edge
		// beside it (a pillar's corner, a shelf); its square windows are
		// candidates of their own.
		std::vector<double> along;
		const OrientedBox& b = clusters[c].box;
		for (uint32_t i : clusters[c].points)
			along.push_back((Eigen::Vector3d(m.xs[i], m.ys[i], m.zs[i]) - b.center).dot(b.axes.col(0)));
		for (const OrientedBox& w : squareWindows(b, radius, planeNoise, cf, along))
		{
			rep.center = w.center;
			rep.extent = w.extent;
			rep.verdict = "candidate";
			out.candidates.push_back(rep);
			candidates.push_back({out.candidates.size() - 1, w});
		}
	}
	tFilter.done(candidates.size());

	report("octree", 0, 1);
	StageTimer tOctree(out, "octree", grid.voxelCount());
	const OctreeGatherer gatherer(grid, params_.gather, threads);
	tOctree.done(gatherer.occupiedLeaves());
	report("octree", 1, 1);

	// Gather, render, decode, solve: independent per candidate. Results are
	// stored per candidate index, so the output is the same for any thread count.
	report("decode", 0, candidates.size());
	StageTimer tDecode(out, "decode", candidates.size());
	std::vector<std::vector<TagDetection>> perCandidate(candidates.size());
	// What a read is judged against (read_evidence.h): the families
	// searched and the orientations each quad was tried in.
	const std::vector<std::string> searched =
		searchFamilies(params_.families.empty() ? parseFamilyList("") : params_.families);
	const int readOrientations = params_.decoder.tryMirrored ? 8 : 4;
	std::mutex progressMutex;
	size_t finished = 0;
	// The tag's normal from the tag and the flat surface around it
	// (support_plane.h): the points within reach, gathered afresh.
	auto orientOnSupport = [&](TagDetection& t, double noise) {
		if (!params_.supportPlane.enabled) return;
		OrientedBox around;
		around.center = t.position();
		around.axes = t.pose.linear();
		const double side = 2 * params_.supportPlane.reachSizes * t.size / params_.gather.enlarge;
		// +-5 sigma of the plane's noise: a slab cut tighter about a plane
		// still tilted would pull the fit towards that tilt.
		const double h = 10 * noise;
		around.extent = Eigen::Vector3d(side, side, h);
		fitSupportPlane(t, gatherer.gather(around, spacing, m.xs, m.ys, m.zs), m.xs, m.ys, m.zs, params_.supportPlane);
	};
	auto sizeAsked = [&](double measured) {
		return params_.tagSize > 0 ? std::abs(measured / params_.tagSize - 1) <= kGivenSizeTolerance
								   : measured >= cf.minTagSize && measured <= cf.maxTagSize;
	};
	parallelForWorkers(candidates.size(), threads, [&](unsigned worker, size_t b, size_t e) {
		const TagDecoder& decoder = decoderFor(worker);
		for (size_t k = b; k < e; k++)
		{
			const OrientedBox& box = candidates[k].box;
			CandidateReport& rep = out.candidates[candidates[k].report];
			const std::vector<uint32_t> pts = gatherer.gather(box, spacing, m.xs, m.ys, m.zs);
			rep.gatheredPoints = pts.size();
			const PlaneImage plane =
				renderIntermediatePlane(m.xs, m.ys, m.zs, m.is, pts, box, spacing, params_.plane);
			rep.verdict = "no_decode";
			if (plane.gray.empty())
			{
				rep.verdict = "not_planar";
				continue;
			}
			if (keepImages) rep.image = plane.gray;
			// Verifies a decode against its own bitmap in 3D; keeps it if it fits.
			auto tryDecoded = [&](const DecodedTag2D& d) {
				// A decode the size of a few points (a code read into text or
				// a corner of a bigger pattern) is no tag of the sizes asked for.
				if (!sizeAsked(measuredTagSize(d, plane)))
				{
					if (rep.verdict != "decoded") rep.verdict = "size_mismatch";
					return;
				}
				TagDetection t = solveTagPose(d, plane, params_.tagSize);
				refitTagPlane(t, plane, m.xs, m.ys, m.zs);
				PatternRefinementParams rp = params_.refinement;
				rp.estimateSize = params_.tagSize <= 0;
				if (!refineWithPattern(t, plane, m.xs, m.ys, m.zs, m.is, rp))
				{
					if (rep.verdict != "decoded") rep.verdict = "pattern_mismatch";
					return;
				}
				refitTagPlane(t, plane, m.xs, m.ys, m.zs);
				if (!sizeAsked(t.size))  // the refined size, too, must be one asked for
				{
					if (rep.verdict != "decoded") rep.verdict = "size_mismatch";
					return;
				}
				orientOnSupport(t, plane.planeRms);
				rep.verdict = "decoded";
				if (keepImages) rep.decodedLabels.push_back(t.family + ":" + std::to_string(t.id));
				perCandidate[k].push_back(std::move(t));
			};
			auto tryAll = [&](std::vector<DecodedTag2D> decoded, const cv::Mat& image, double scale) {
				for (DecodedTag2D& d : decoded)
				{
					// Judged on the image it was read from, before anything costly.
					const ReadEvidence ev = assessRead(image, d, readOrientations, searched, params_.evidence);
					for (auto& c : d.corners) c *= scale;
					if (keepImages) rep.decoded.push_back(d);
					if (!ev.rejection.empty())
					{
						if (rep.verdict != "decoded") rep.verdict = ev.rejection;
						continue;
					}
					tryDecoded(d);
				}
				return !perCandidate[k].empty();
			};
			// The raw image's quads serve its ArUco decode and the soft decoder.
			const std::vector<Quad> quads = findTagQuads(plane.gray, params_.decoder.maxQuads);
			bool found = false;
			for (const ImageVariant& variant : makeImageVariants(plane.gray, params_.imageVariants))
				if ((found = tryAll(decoder.decode(variant.gray, variant.gray.data == plane.gray.data ? &quads : nullptr),
									variant.gray, variant.scale)))
					break;
			// Last resort for blurred tags: correlate quads with every code.
			if (!found) tryAll(softDecoderFor(worker).decode(plane.gray, quads), plane.gray, 1.0);
			std::lock_guard<std::mutex> lock(progressMutex);
			report("decode", ++finished, candidates.size());
		}
	});
	std::vector<TagDetection> all;
	for (auto& v : perCandidate)
		for (auto& t : v) all.push_back(std::move(t));
	tDecode.done(all.size());

	StageTimer tMerge(out, "merge", all.size());
	out.tags = mergeDetections(std::move(all));
	tMerge.done(out.tags.size());
	out.totalSeconds = std::chrono::duration<double>(Clock::now() - tStart).count();
	return out;
}

}  // namespace tagmap
