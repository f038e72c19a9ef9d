#include "tagmap/pipeline.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <limits>
#include <mutex>
#include <optional>
#include <type_traits>

#include "tagmap/candidate_filter.h"
#include "tagmap/clustering.h"
#include "tagmap/code_in_points.h"
#include "tagmap/derived_lengths.h"
#include "tagmap/intensity_gradient.h"
#include "tagmap/image_variants.h"
#include "tagmap/intermediate_plane.h"
#include "tagmap/merge_detections.h"
#include "tagmap/octree_gather.h"
#include "tagmap/parallel.h"
#include "tagmap/pattern_refinement.h"
#include "tagmap/point_spacing.h"
#include "tagmap/read_evidence.h"
#include "tagmap/sensor_view.h"
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

/** Fewer points than this: no map to look for tags in. */
constexpr size_t kMinMapPoints = 16;

// What a stage reports as its items out (Detections::stages), by what it returns.
size_t itemsOut(double /*spacing*/) { return 1; }
size_t itemsOut(size_t count) { return count; }
size_t itemsOut(const VoxelGrid& grid) { return grid.voxelCount(); }
size_t itemsOut(const IntensityGradientResult& r) { return r.keptPoints.size(); }
size_t itemsOut(const std::unique_ptr<const OctreeGatherer>& g) { return g->occupiedLeaves(); }
// A scan's view and what the decoders read in it (sensor_view.h).
struct SensorViewReads
{
	SensorView view;
	std::vector<DecodedTag2D> reads;
};
size_t itemsOut(const SensorViewReads& r) { return r.reads.size(); }
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

// Everything one candidate needs from the map, in one place.
struct MapView
{
	const float *xs, *ys, *zs, *is;
	size_t n;

	explicit MapView(const mrpt::maps::CPointsMapXYZI& map)
		: xs(map.getPointsBufferRef_x().data()),
		  ys(map.getPointsBufferRef_y().data()),
		  zs(map.getPointsBufferRef_z().data()),
		  is(map.getPointsBufferRef_intensity().data()),
		  n(map.size())
	{
	}
	MapView(const float* x, const float* y, const float* z, const float* i, size_t count)
		: xs(x), ys(y), zs(z), is(i), n(count)
	{
	}
	Eigen::Vector3d point(uint32_t i) const { return {xs[i], ys[i], zs[i]}; }
};

// Some of a map's points, copied into a map of their own.
struct PointsSubset
{
	std::vector<uint32_t> indices;  // in the map they were copied from, ascending
	std::vector<float> xs, ys, zs, is;
	PointsSubset(const MapView& m, std::vector<uint32_t> from) : indices(std::move(from))
	{
		for (auto* v : {&xs, &ys, &zs, &is}) v->reserve(indices.size());
		for (uint32_t i : indices)
		{
			xs.push_back(m.xs[i]);
			ys.push_back(m.ys[i]);
			zs.push_back(m.zs[i]);
			is.push_back(m.is[i]);
		}
	}
	MapView view() const { return {xs.data(), ys.data(), zs.data(), is.data(), xs.size()}; }
};
size_t itemsOut(const PointsSubset& s) { return s.xs.size(); }

// Clusters at several tolerances: the point spacing varies across a map
// (near and far views, overlapping passes), and a tag scanned more sparsely
// than the map's median breaks into fragments at the finest tolerance. A
// coarser one re-joins it; identical clusters are kept once. `levelScale`:
// the density level's radius multiple (1, 3, 9 ...). Returns the clusters
// in all.
size_t addClusters(const MapView& m, const std::vector<uint32_t>& kept, double levelScale, double spacing,
				   const ClusteringParams& p, std::vector<Cluster>& clusters)
{
	for (double scale : p.scales)
		for (Cluster& c :
			 clusterPoints(m.xs, m.ys, m.zs, kept, levelScale * scale * p.toleranceSpacings * spacing, p.minPoints))
		{
			const bool seen = std::any_of(clusters.begin(), clusters.end(), [&](const Cluster& o) {
				return o.points.size() == c.points.size() && o.points.front() == c.points.front();
			});
			if (!seen) clusters.push_back(std::move(c));
		}
	return clusters.size();
}

// The candidate filter as asked: --tag-size, when given, is the only size.
CandidateFilterParams filterParams(const PipelineParams& p)
{
	CandidateFilterParams cf = p.candidates;
	if (p.tagSize > 0) cf.tagSize = p.tagSize;
	return cf;
}

// A cluster too large for any tag asked for may be a plain wall whose noise
// passed the gradient's fixed bars (range noise thicker than r, strong
// intensity noise), with a tag on it. Its points that beat chance
// (IntensityGradientResult::keptByChance) are clustered again: the tag's
// edges then stand apart. Only such clusters, which yield nothing as they
// are, so no candidate of today is lost. Adds to `clusters`; returns the
// points re-clustered.
size_t splitOversizedClusters(const MapView& m, const std::vector<uint32_t>& keptByChance, double spacing,
							  const DerivedLengths& len, const PipelineParams& p, std::vector<Cluster>& clusters)
{
	if (keptByChance.empty()) return 0;
	const CandidateFilterParams cf = filterParams(p);
	std::vector<uint32_t> significant;
	for (size_t k = 0, before = clusters.size(); k < before; k++)
	{
		if (!tooLargeForATag(clusters[k].box, len.candidateBand, cf)) continue;
		for (uint32_t i : clusters[k].points)
			if (!std::binary_search(keptByChance.begin(), keptByChance.end(), i)) significant.push_back(i);
	}
	std::sort(significant.begin(), significant.end());
	significant.erase(std::unique(significant.begin(), significant.end()), significant.end());
	addClusters(m, significant, 1.0, spacing, p.clustering, clusters);
	return significant.size();
}

// Density levels: where the map is sparser than its median (far from the
// sensor, a fast pass), a point has too few neighbours within r to fit a
// gradient. Those points alone are run again at 3x the radius and clustered
// at 3x the tolerance, and so on, so the result follows the local spacing,
// not the map's densest part. Adds to `clusters`; returns the points kept.
size_t clusterSparseLevels(const MapView& m, IntensityGradientResult level, const DerivedLengths& len,
						   const PipelineParams& p, unsigned threads, std::vector<Cluster>& clusters)
{
	size_t kept = 0;
	double levelScale = 1;
	for (int l = 1; l < p.gradient.densityLevels && level.sparsePoints.size() >= p.clustering.minPoints; l++)
	{
		levelScale *= 3;
		const std::vector<uint32_t> subset = std::move(level.sparsePoints);
		std::vector<float> sx(subset.size()), sy(subset.size()), sz(subset.size()), si(subset.size());
		for (size_t k = 0; k < subset.size(); k++)
			sx[k] = m.xs[subset[k]], sy[k] = m.ys[subset[k]], sz[k] = m.zs[subset[k]], si[k] = m.is[subset[k]];
		const VoxelGrid subGrid(sx.data(), sy.data(), sz.data(), subset.size(), levelScale * len.voxelCell, threads);
		level = filterByIntensityGradient(sx.data(), sy.data(), sz.data(), si.data(), subGrid,
										  levelScale * len.gradientRadius, p.gradient, threads, level.intensitySpread);
		for (auto* v : {&level.keptPoints, &level.sparsePoints})
			for (auto& k : *v) k = subset[k];  // back to map indices (still ascending)
		kept += level.keptPoints.size();
		addClusters(m, level.keptPoints, levelScale, len.spacing, p.clustering, clusters);
	}
	return kept;
}

// A candidate: the box to gather around, and the report it fills in.
struct Candidate
{
	size_t report;  // into Detections::candidates
	OrientedBox box;
	/** libapriltag read an AprilTag here in the scan's sensor view: the
	 *  candidate image is read by it first, before any clutter test. */
	bool aprilTagInView = false;
};

// Stage 3 over every cluster: a report each, and the boxes that may hold a
// tag: the cluster's own, or for a box too long for a tag (maybe a tag
// clustered together with an edge beside it: a pillar's corner, a shelf)
// its square windows, candidates of their own.
std::vector<Candidate> proposeCandidates(const MapView& m, const std::vector<Cluster>& clusters,
										 const CandidateFilterParams& cf, const DerivedLengths& len,
										 std::vector<CandidateReport>& reports)
{
	std::vector<Candidate> candidates;
	for (const Cluster& c : clusters)
	{
		const std::optional<Verdict> why = rejectCandidate(c.box, len.candidateBand, len.planeNoise, cf);
		CandidateReport rep;
		rep.center = c.box.center;
		rep.extent = c.box.extent;
		rep.clusterPoints = c.points.size();
		rep.verdict = why.value_or(Verdict::Candidate);
		reports.push_back(rep);
		if (!why) candidates.push_back({reports.size() - 1, c.box});
		if (why != Verdict::Squareness) continue;
		std::vector<double> along;
		for (uint32_t i : c.points) along.push_back((m.point(i) - c.box.center).dot(c.box.axes.col(0)));
		for (const OrientedBox& w : squareWindows(c.box, len.candidateBand, len.planeNoise, cf, along))
		{
			rep.center = w.center;
			rep.extent = w.extent;
			rep.verdict = Verdict::Candidate;
			reports.push_back(rep);
			candidates.push_back({reports.size() - 1, w});
		}
	}
	return candidates;
}

// The fewest and the most cells across a border square among `families`
// (aruco_4x4: 6, aruco_7x7: 9); both 0 when there are none.
struct BorderCellsRange
{
	int fewest = 0, most = 0;
};
BorderCellsRange borderCellsAcross(const std::vector<std::string>& families)
{
	BorderCellsRange r;
	for (const std::string& f : families)
	{
		const int cells = findFamily(f)->borderCells;
		r.fewest = r.fewest > 0 ? std::min(r.fewest, cells) : cells;
		r.most = std::max(r.most, cells);
	}
	return r;
}

// Stages 1-3 for a scan in its sensor frame (sensor_view.h), first half:
// the scan as its sensor sees it and every read of it, by libapriltag and
// by the soft decoder. Needs none of the scan's measured lengths.
SensorViewReads readSensorView(const MapView& m, const PipelineParams& p, const std::vector<std::string>& families,
							   const TagDecoder& hard, const SoftTagDecoder& soft)
{
	SensorViewReads out{renderSensorView(m.xs, m.ys, m.zs, m.is, m.n, p.sensorView), {}};
	if (out.view.gray.empty()) return out;
	// The smallest tag a scan can show: a point on every cell of the family
	// with the fewest cells across its border square.
	const int fewestCells = borderCellsAcross(families).fewest;
	const std::vector<Quad> quads =
		findTagQuads(out.view.gray, p.sensorView.maxQuads, fewestCells * out.view.angularSpacing / out.view.pixel);
	out.reads = hard.decode(out.view.gray, &quads);
	for (DecodedTag2D& d : soft.decode(out.view.gray, quads)) out.reads.push_back(std::move(d));
	return out;
}

// Second half: the box around each read's corners (from the scan's points
// `near` the reads); reads of one quad (plain and mirrored, hard and soft)
// propose it once. Each box passes the same size, squareness and flatness
// criteria as a cluster's.
std::vector<Candidate> proposeFromSensorView(const MapView& m, const SensorViewReads& seen,
											 const std::vector<uint32_t>& near, const PipelineParams& p,
											 const DerivedLengths& len, std::vector<CandidateReport>& reports)
{
	std::vector<Candidate> candidates;
	const CandidateFilterParams cf = filterParams(p);
	for (const DecodedTag2D& d : seen.reads)
	{
		OrientedBox box;
		if (!boxOfRead(seen.view, d, m.xs, m.ys, m.zs, near, len.candidateBand, box)) continue;
		const bool again = std::any_of(candidates.begin(), candidates.end(), [&](const Candidate& c) {
			return (c.box.center - box.center).norm() < 0.25 * std::min(box.extent.x(), box.extent.y());
		});
		if (again) continue;
		CandidateReport rep;
		rep.center = box.center;
		rep.extent = box.extent;
		const std::optional<Verdict> why = rejectCandidate(box, len.candidateBand, len.planeNoise, cf);
		rep.verdict = why.value_or(Verdict::Candidate);
		reports.push_back(rep);
		const TagFamilyInfo* family = findFamily(d.family);
		const bool aprilTag = family && family->system == TagSystem::AprilTag && d.hamming >= 0;  // not a soft read
		if (!why) candidates.push_back({reports.size() - 1, box, aprilTag});
	}
	return candidates;
}

// A candidate's verdict after a failed check; a tag already decoded on it
// (another read of the same image) is kept.
void reject(CandidateReport& rep, Verdict why)
{
	if (rep.verdict != Verdict::Decoded) rep.verdict = why;
}

// What decoding one candidate gives: its tags and its report.
struct CandidateOutcome
{
	std::vector<TagDetection> tags;
	CandidateReport report;
	/** A read whose family's grid reaches past the image (the candidate's
	 *  box cut the tag off): the box its whole grid fits in. */
	std::optional<OrientedBox> readCutOff;
};

// The families a detection searches (all of them when none are named).
std::vector<std::string> familiesAsked(const PipelineParams& p)
{
	return p.families.empty() ? parseFamilyList("") : p.families;
}

// The smallest border square a detection can report: --tag-size less its
// tolerance, else candidates.min_tag_size.
double smallestSideAsked(const PipelineParams& p)
{
	return p.tagSize > 0 ? p.tagSize * (1 - kGivenSizeTolerance) : p.candidates.minTagSize;
}

// The smallest cell of any tag a detection can report: the smallest size
// asked for over the most cells across a border square of the families
// decoded (aruco_7x7: 9); 0 when none. The images need not resolve anything
// finer (IntermediatePlaneParams::pixelsPerCell). Not the smallest the
// box's size implies: tags far smaller than their box are found too (a
// 0.17 m tag in a 3 m window of a sparse wall).
double smallestReportableCell(const PipelineParams& p, const std::vector<std::string>& families)
{
	const int most = borderCellsAcross(families).most;
	return most > 0 ? smallestSideAsked(p) / most : 0;
}

// The orientations each quad is read in: 4 rotations, each also mirrored.
int readOrientations(const PipelineParams& p) { return p.decoder.tryMirrored ? 8 : 4; }

// Stages 4-6 for one candidate at a time: gather, render, decode, verify,
// pose. Fixed for the whole map, shared by the worker threads.
class CandidateDecoder
{
   public:
	CandidateDecoder(const PipelineParams& p, const MapView& m, const OctreeGatherer& gatherer,
					 const DerivedLengths& len, bool keepImages, const std::vector<std::string>& decodedFamilies)
		: p_(p),
		  m_(m),
		  gatherer_(gatherer),
		  len_(len),
		  keepImages_(keepImages),
		  sizes_(filterParams(p)),
		  // What a read is judged against (read_evidence.h): the families
		  // searched and the orientations each quad was tried in.
		  searched_(searchFamilies(familiesAsked(p))),
		  readOrientations_(readOrientations(p)),
		  fewestPoints_(static_cast<size_t>(fewestCellsToRead(decodedFamilies))),
		  smallestCell_(smallestReportableCell(p, decodedFamilies)),
		  decodedFamilies_(decodedFamilies),
		  refinement_(refinementFor(p)),
		  secondPlacementEvidence_(halfBudget(p.evidence))
	{
	}

	/** The candidate's tags and its report (`rep`, with what happened). A
	 *  read cut off by the candidate's image is decoded once more on an
	 *  image of the box its whole grid fits in: families with data cells
	 *  outside their border (tagStandard41h12, tagCircle49h12: 1.7-2.2 times
	 *  the border across) reach past a box drawn around part of the tag. */
	CandidateOutcome decodeCandidate(const Candidate& candidate, CandidateReport rep, const TagDecoder& hard,
									 const SoftTagDecoder& soft) const
	{
		CandidateOutcome out = decodeBox(candidate, std::move(rep), hard, soft);
		if (!out.tags.empty() || !out.readCutOff) return out;
		Candidate recentred = candidate;
		recentred.box = *out.readCutOff;
		recentred.box.extent.z() = candidate.box.extent.z();  // the same slab about the plane
		CandidateOutcome again = decodeBox(recentred, out.report, hard, soft);
		return again.tags.empty() ? out : again;
	}

   private:
	CandidateOutcome decodeBox(const Candidate& candidate, CandidateReport rep, const TagDecoder& hard,
							   const SoftTagDecoder& soft) const
	{
		const OrientedBox& box = candidate.box;
		CandidateOutcome out{{}, std::move(rep), std::nullopt};
		if (decodedFamilies_.empty())
		{
			out.report.verdict = Verdict::NoFamilyCanPass;
			return out;
		}
		const std::vector<uint32_t> pts = gatherer_.gather(box, len_.spacing, m_.xs, m_.ys, m_.zs);
		out.report.gatheredPoints = pts.size();
		// The cheapest sure test, before any image is made: every cell a
		// read relies on needs a point of its own.
		if (pts.size() < fewestPoints_)
		{
			out.report.verdict = Verdict::TooFewPoints;
			return out;
		}
		const PlaneImage plane =
			renderIntermediatePlane(m_.xs, m_.ys, m_.zs, m_.is, pts, box, len_.spacing, p_.plane, smallestCell_);
		out.report.verdict = Verdict::NoDecode;
		if (plane.gray.empty())
		{
			out.report.verdict = Verdict::NotPlanar;
			return out;
		}
		if (keepImages_) out.report.image = plane.gray;
		// Where the sensor view read an AprilTag, libapriltag on the raw
		// image first: the quad search and the look below sort clutter out,
		// and a tag it reads here needs neither (the raw image's decode with
		// the quads adds only ArUco reads of them).
		const std::vector<Quad> noQuads;
		if (candidate.aprilTagInView && tryReads(hard.decode(plane.gray, &noQuads), plane.gray, 1.0, plane, out))
			return out;
		// The raw image's quads serve the ArUco decode of every variant and
		// the soft decoder: they already hold the Otsu dark-blob outlines,
		// so searching the binarised and half-size variants again found the
		// same squares at twice the cost.
		std::vector<Quad> quads = findTagQuads(plane.gray, std::numeric_limits<int>::max());
		// The cheapest sure test on the image: most clutter (window grids)
		// has outlines only of one colour inside, or too small to be a tag.
		// libapriltag, the costliest decoder, would search it three times.
		// Every outline is looked at, not only the largest the decoders get:
		// libapriltag finds its own, and a small tag in a busy image may be
		// outline number 9.
		if (std::none_of(quads.begin(), quads.end(), [&](const Quad& q) { return mayShowATag(q, plane); }))
		{
			out.report.verdict = Verdict::NoCodeShown;
			return out;
		}
		quads.resize(std::min(quads.size(), static_cast<size_t>(std::max(0, p_.decoder.maxQuads))));  // largest first
		for (const ImageVariant& variant : makeImageVariants(plane.gray, p_.imageVariants))
		{
			const std::vector<Quad> variantQuads = scaledQuads(quads, 1.0 / variant.scale);
			if (tryReads(hard.decode(variant.gray, &variantQuads), variant.gray, variant.scale, plane, out))
				return out;
		}
		// Last resort for blurred tags: correlate quads with every code.
		tryReads(soft.decode(plane.gray, quads, &plane.measured), plane.gray, 1.0, plane, out);
		return out;
	}

	// Judges each read on the image it was read from, before anything
	// costly, then in 3D; true when the candidate has a tag.
	bool tryReads(std::vector<DecodedTag2D> reads, const cv::Mat& image, double scale, const PlaneImage& plane,
				  CandidateOutcome& out) const
	{
		for (DecodedTag2D& d : reads)
		{
			ReadEvidence ev = judgeRead(image, d, scale, plane, p_.evidence);
			// A quad traced on a noisy or blurred border can sit a fraction
			// of a cell off, and the cells along its edges then read their
			// neighbours, or its grid off the image. A read rejected as by
			// chance or off the image is judged again on the grid its
			// family's frame places (placeByFrame(): no code favoured), at
			// half the budget: the two placements together stay within one
			// and a half budgets.
			if ((ev.rejection == Verdict::ByChance || ev.rejection == Verdict::GridOffImage) && scale == 1)
				if (std::optional<DecodedTag2D> placed = placedByFrame(d, plane))
				{
					ReadEvidence again = judgeRead(image, *placed, scale, plane, secondPlacementEvidence_);
					if (!again.rejection) d = std::move(*placed), ev = std::move(again);
				}
			for (auto& c : d.corners) c *= scale;
			if (ev.rejection == Verdict::GridOffImage && !out.readCutOff) out.readCutOff = wholeGridBox(d, plane);
			TagDetection t;
			const Verdict v = ev.rejection ? *ev.rejection : verifyRead(d, ev, plane, t);
			if (keepImages_)
			{
				out.report.decoded.push_back(d);
				out.report.readVerdicts.push_back(v);
			}
			if (v != Verdict::Decoded)
			{
				reject(out.report, v);
				continue;
			}
			out.report.verdict = Verdict::Decoded;
			if (keepImages_) out.report.decodedLabels.push_back(tagLabel(t.family, t.id));
			out.tags.push_back(std::move(t));
		}
		return !out.tags.empty();
	}

	// The evidence of a read on `image`. Cells in a gap of the scan hold the
	// hole filling's guesses: a read they fail is judged again on the
	// scanned cells alone.
	ReadEvidence judgeRead(const cv::Mat& image, const DecodedTag2D& d, double scale, const PlaneImage& plane,
						   const ReadEvidenceParams& ep) const
	{
		ReadEvidence ev = assessRead(image, d, readOrientations_, searched_, ep);
		if (ev.rejection && scale == 1)
		{
			ReadEvidence scanned = assessMeasuredRead(image, plane.measured, d, readOrientations_, searched_, ep);
			if (!scanned.rejection) ev = std::move(scanned);
		}
		return ev;
	}

	// The read with its quad moved to where its family's frame fits the
	// points best (on the plane image `d` was read from); nothing when its
	// size is none asked for or too few points lie on its grid.
	std::optional<DecodedTag2D> placedByFrame(const DecodedTag2D& d, const PlaneImage& plane) const
	{
		if (!sizeAsked(measuredTagSize(d, plane))) return std::nullopt;
		TagDetection t = solveTagPose(d, plane, p_.tagSize);
		if (!placeByFrame(t, plane, m_.xs, m_.ys, m_.zs, m_.is, refinement_)) return std::nullopt;
		DecodedTag2D placed = d;
		for (int k = 0; k < 4; k++) placed.corners[k] = plane.frame.toImage(t.corners[k]);
		return placed;
	}

	// A read in 3D: pose, plane refit, the tag's own bitmap fitted to its
	// points, the size asked for, the code on the cells the points measured,
	// the support plane, the side it faces. Verdict::Decoded and `t` when it
	// holds.
	Verdict verifyRead(const DecodedTag2D& d, const ReadEvidence& ev, const PlaneImage& plane, TagDetection& t) const
	{
		// A decode the size of a few points (a code read into text or a
		// corner of a bigger pattern) is no tag of the sizes asked for.
		if (!sizeAsked(measuredTagSize(d, plane))) return Verdict::SizeMismatch;
		t = solveTagPose(d, plane, p_.tagSize);
		refitTagPlane(t, plane, m_.xs, m_.ys, m_.zs);
		if (!refineWithPattern(t, plane, m_.xs, m_.ys, m_.zs, m_.is, refinement_)) return Verdict::PatternMismatch;
		refitTagPlane(t, plane, m_.xs, m_.ys, m_.zs);
		if (!sizeAsked(t.size)) return Verdict::SizeMismatch;  // the refined size, too, must be one asked for
		if (!measuredCellsShowTheCode(d, ev, plane, t)) return Verdict::CodeNotInPoints;
		orientOnSupport(t, plane.planeRms);
		return facesFreeSpace(t) ? Verdict::Decoded : Verdict::WrongSide;
	}

	// The code in the points, not only in the image (code_in_points.h): the
	// read judged again on the cells of the image it was read from with
	// those no point falls in erased, and the points' own read nearer the
	// decoded code than any other code. True when both hold.
	bool measuredCellsShowTheCode(const DecodedTag2D& d, const ReadEvidence& ev, const PlaneImage& plane,
								  const TagDetection& t) const
	{
		const std::vector<float> points = cellMeansFromPoints(t, plane, m_.xs, m_.ys, m_.zs, m_.is);
		if (judgeCells(eraseUnmeasured(ev.cells, points), t.family, t.id, d.hamming, readOrientations_, searched_,
					   p_.evidence)
				.rejection)
			return false;
		const CodeDistances c = codeDistances(points, t.family, t.id, readOrientations_, p_.evidence);
		return c.toOwn < c.toNearestOther;
	}

	// An outline a tag of a size asked for could have, with both colours
	// inside. Outlines on a blurred image lie within a cell of the border
	// they follow: half the smallest side asked for is far below any read's.
	bool mayShowATag(const Quad& q, const PlaneImage& plane) const
	{
		return measuredTagSize(q, plane) >= 0.5 * smallestSideAsked(p_) &&
			   quadCanShowACode(plane.gray, q, decodedFamilies_, p_.evidence);
	}

	bool sizeAsked(double measured) const
	{
		return p_.tagSize > 0 ? std::abs(measured / p_.tagSize - 1) <= kGivenSizeTolerance
							  : measured >= sizes_.minTagSize && measured <= sizes_.maxTagSize;
	}

	// The tag's normal from the tag and the flat surface around it
	// (support_plane.h): the points within reach, gathered afresh.
	void orientOnSupport(TagDetection& t, double noise) const
	{
		if (!p_.supportPlane.enabled) return;
		OrientedBox around;
		around.center = t.position();
		around.axes = t.pose.linear();
		const double side = 2 * p_.supportPlane.reachSizes * t.size / p_.gather.enlarge;
		// +-5 sigma of the plane's noise: a slab cut tighter about a plane
		// still tilted would pull the fit towards that tilt.
		const double h = 10 * noise;
		around.extent = Eigen::Vector3d(side, side, h);
		fitSupportPlane(t, gatherer_.gather(around, len_.spacing, m_.xs, m_.ys, m_.zs), m_.xs, m_.ys, m_.zs,
						p_.supportPlane);
	}

	// The read's printed face looks into free space (front_side.h): the
	// columns in front of and behind the tag, a few tag sizes deep.
	bool facesFreeSpace(const TagDetection& t) const
	{
		if (!p_.frontSide.enabled) return true;
		OrientedBox both;
		both.center = t.position();
		both.axes = t.pose.linear();
		// gather() widens the box by `enlarge` and thickens it by its slab.
		both.extent = Eigen::Vector3d(t.size / p_.gather.enlarge, t.size / p_.gather.enlarge,
									  2 * p_.frontSide.depthSizes * t.size);
		const FrontSideEvidence e = measureFrontSide(t, gatherer_.gather(both, len_.spacing, m_.xs, m_.ys, m_.zs),
													 m_.xs, m_.ys, m_.zs, 2 * len_.planeNoise, p_.frontSide);
		return !printedFaceLooksIntoSolid(e, p_.frontSide);
	}

	const PipelineParams& p_;
	const MapView& m_;
	const OctreeGatherer& gatherer_;
	const DerivedLengths len_;
	const bool keepImages_;
	const CandidateFilterParams sizes_;
	const std::vector<std::string> searched_;
	const int readOrientations_;
	const size_t fewestPoints_;  // fewestCellsToRead() of the families decoded
	const double smallestCell_;  // smallestReportableCell(): the finest the images need resolve
	const std::vector<std::string> decodedFamilies_;  // what the decoders search
	const PatternRefinementParams refinement_;  // the size floats unless --tag-size was given
	const ReadEvidenceParams secondPlacementEvidence_;  // half the chance budget

	static PatternRefinementParams refinementFor(const PipelineParams& p)
	{
		PatternRefinementParams rp = p.refinement;
		rp.estimateSize = p.tagSize <= 0;
		return rp;
	}
	static ReadEvidenceParams halfBudget(ReadEvidenceParams e)
	{
		e.chanceBudget /= 2;
		return e;
	}
};

// Gather, render, decode, solve: independent per candidate, on each
// worker's own decoders. Results are stored per candidate index, so the
// output is the same for any thread count. Reports candidates done.
template <typename DecodersFor>
std::vector<TagDetection> decodeCandidates(const CandidateDecoder& decoder, const std::vector<Candidate>& candidates,
										   std::vector<CandidateReport>& reports, unsigned threads,
										   const CountProgressFn& progress, DecodersFor&& decodersFor)
{
	std::vector<std::vector<TagDetection>> perCandidate(candidates.size());
	std::atomic<size_t> finished{0};
	parallelForWorkers(candidates.size(), threads, [&](unsigned worker, size_t b, size_t e) {
		const auto decoders = decodersFor(worker);
		for (size_t k = b; k < e; k++)
		{
			CandidateReport& rep = reports[candidates[k].report];
			CandidateOutcome o = decoder.decodeCandidate(candidates[k], std::move(rep), decoders.hard, decoders.soft);
			rep = std::move(o.report);
			perCandidate[k] = std::move(o.tags);
			progress(++finished, candidates.size());
		}
	});
	std::vector<TagDetection> all;
	for (auto& v : perCandidate)
		for (auto& t : v) all.push_back(std::move(t));
	return all;
}

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
	stage.run("oversized_split", edges.keptByChance.size(), [&] {
		return splitOversizedClusters(m, edges.keptByChance, len.spacing, len, p, clusters);
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

Pipeline::WorkerDecoders Pipeline::decodersFor(unsigned worker) const
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
	const CandidateDecoder decoder(params_, m, *gatherer, len, keepImages, decodedFamilies_);
	std::vector<TagDetection> found = stage.run("decode", candidates.size(), [&](const CountProgressFn& count) {
		return decodeCandidates(decoder, candidates, out.candidates, threads, count,
								[this](unsigned worker) { return decodersFor(worker); });
	});
	out.tags = stage.run("merge", found.size(), [&] { return mergeDetections(std::move(found), params_.merge); });
	out.totalSeconds = std::chrono::duration<double>(Clock::now() - tStart).count();
	return out;
}

}  // namespace tagmap
