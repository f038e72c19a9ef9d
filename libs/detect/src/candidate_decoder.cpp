#include "candidate_decoder.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <limits>
#include <optional>

#include "tagmap/code_in_points.h"
#include "tagmap/decode_schedule.h"
#include "tagmap/front_side.h"
#include "tagmap/image_variants.h"
#include "tagmap/intermediate_plane.h"
#include "tagmap/parallel.h"
#include "tagmap/pattern_refinement.h"
#include "tagmap/read_evidence.h"
#include "tagmap/support_plane.h"
#include "tagmap/tag_family.h"
#include "tagmap/tag_pose.h"

namespace tagmap::detail
{
namespace
{
// A candidate's verdict after a failed check; a tag already decoded on it
// (another read of the same image) is kept.
void reject(CandidateReport& rep, Verdict why)
{
	if (rep.verdict != Verdict::Decoded) rep.verdict = why;
}

// The tags a candidate's group decoded before it, each with the index of
// the report of the candidate that decoded it (decode_schedule.h).
using EarlierTags = std::vector<std::pair<const TagDetection*, size_t>>;

// The report index of the earlier tag `point` lies on, if any.
std::optional<size_t> earlierTagAt(const Eigen::Vector3d& point, const EarlierTags& earlier)
{
	for (const auto& [tag, report] : earlier)
		if (onDecodedTag(point, *tag)) return report;
	return std::nullopt;
}

Eigen::Vector2d centreOf(const Quad& q) { return 0.25 * (q[0] + q[1] + q[2] + q[3]); }

// What decoding one candidate gives: its tags and its report.
struct CandidateOutcome
{
	std::vector<TagDetection> tags;
	CandidateReport report;
	/** A read whose family's grid reaches past the image (the candidate's
	 *  box cut the tag off): the box its whole grid fits in. */
	std::optional<OrientedBox> readCutOff;
};

// Stages 4-6 for one candidate at a time: gather, render, decode, verify,
// pose. Fixed for the whole map, shared by the worker threads.
class CandidateDecoder
{
   public:
	CandidateDecoder(const PipelineParams& p, const MapView& m, const VoxelGrid& grid, const OctreeGatherer& gatherer,
					 const std::vector<Eigen::Vector3d>& viewpoints, const DerivedLengths& len, bool keepImages,
					 const std::vector<std::string>& decodedFamilies)
		: p_(p),
		  m_(m),
		  grid_(grid),
		  gatherer_(gatherer),
		  viewpoints_(viewpoints),
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
	 *  the border across) reach past a box drawn around part of the tag.
	 *  Outlines and reads on a tag of `earlier` are not decoded or verified
	 *  again. */
	CandidateOutcome decodeCandidate(const Candidate& candidate, CandidateReport rep, const TagDecoder& hard,
									 const SoftTagDecoder& soft, const EarlierTags& earlier) const
	{
		CandidateOutcome out = decodeBox(candidate, std::move(rep), hard, soft, earlier);
		if (!out.tags.empty() || !out.readCutOff) return out;
		Candidate recentred = candidate;
		recentred.box = *out.readCutOff;
		recentred.box.extent.z() = candidate.box.extent.z();  // the same slab about the plane
		CandidateOutcome again = decodeBox(recentred, out.report, hard, soft, earlier);
		return again.tags.empty() ? out : again;
	}

   private:
	CandidateOutcome decodeBox(const Candidate& candidate, CandidateReport rep, const TagDecoder& hard,
							   const SoftTagDecoder& soft, const EarlierTags& earlier) const
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
		// Where the sensor view read a tag, the soft decoder first reads the
		// image on the view's quad (0.05 ms), then, for a read of
		// libapriltag's, libapriltag the raw image (0.45 ms). The outline
		// search, the look below and the decoders' variants sort clutter
		// out; a tag read here needs none of them. The view's quad is read
		// as the view read it: families with white border rings are
		// libapriltag's there (SoftTagDecoder::decode).
		if (candidate.cornersInView)
		{
			Quad inView;
			for (int k = 0; k < 4; k++) inView[k] = plane.frame.toImage((*candidate.cornersInView)[k]);
			if (tryReads(soft.decode(plane.gray, {inView}, &plane.measured, false), plane.gray, 1.0, plane, earlier,
						 out))
				return out;
		}
		const std::vector<Quad> noQuads;
		if (candidate.aprilTagInView &&
			tryReads(hard.decode(plane.gray, &noQuads), plane.gray, 1.0, plane, earlier, out))
			return out;
		// The raw image's quads serve the ArUco decode of every variant and
		// the soft decoder: they already hold the Otsu dark-blob outlines,
		// so searching the binarised and half-size variants again found the
		// same squares at twice the cost.
		std::vector<Quad> quads = findTagQuads(plane.gray, std::numeric_limits<int>::max());
		// Outlines on a tag the group decoded before: the box holds it off
		// its centre (density levels, square windows, its board's outline:
		// 1.5-2.4 times its size around it), and a read there would be that
		// tag again. What else the box holds is still decoded.
		std::optional<size_t> onTagOf;
		quads.erase(std::remove_if(quads.begin(), quads.end(),
								   [&](const Quad& q) {
									   const auto on = earlierTagAt(plane.frame.toMap(centreOf(q)), earlier);
									   if (on && !onTagOf) onTagOf = on;
									   return on.has_value();
								   }),
					quads.end());
		// The cheapest sure test on the image: most clutter (window grids)
		// has outlines only of one colour inside, or too small to be a tag.
		// libapriltag, the costliest decoder, would search it three times.
		// Every outline is looked at, not only the largest the decoders get:
		// libapriltag finds its own, and a small tag in a busy image may be
		// outline number 9. ArUco and the soft decoder read the largest
		// outlines as they are, and of those only the ones that pass: a read
		// on the others (a window grid's panes) could not (quadCanShowACode).
		const size_t largest = std::min(quads.size(), static_cast<size_t>(std::max(0, p_.decoder.maxQuads)));
		const auto mayShowIt = [&](const Quad& q) { return mayShowATag(q, plane); };
		std::vector<Quad> mayShow;  // of the largest
		std::copy_if(quads.begin(), quads.begin() + static_cast<std::ptrdiff_t>(largest), std::back_inserter(mayShow),
					 mayShowIt);
		if (mayShow.empty() && std::none_of(quads.begin() + static_cast<std::ptrdiff_t>(largest), quads.end(), mayShowIt))
		{
			out.report.verdict = onTagOf ? Verdict::OnDecodedTag : Verdict::NoCodeShown;
			if (!out.report.onTagOf) out.report.onTagOf = onTagOf;
			return out;
		}
		quads = std::move(mayShow);
		for (const ImageVariant& variant : makeImageVariants(plane.gray, p_.imageVariants))
		{
			const std::vector<Quad> variantQuads = scaledQuads(quads, 1.0 / variant.scale);
			if (tryReads(hard.decode(variant.gray, &variantQuads), variant.gray, variant.scale, plane, earlier, out))
				return out;
		}
		// Last resort for blurred tags: correlate quads with every code.
		tryReads(soft.decode(plane.gray, quads, &plane.measured), plane.gray, 1.0, plane, earlier, out);
		return out;
	}

	// Judges each read on the image it was read from, before anything
	// costly, then in 3D; true when the candidate has a tag.
	bool tryReads(std::vector<DecodedTag2D> reads, const cv::Mat& image, double scale, const PlaneImage& plane,
				  const EarlierTags& earlier, CandidateOutcome& out) const
	{
		// What became of read `d` (corners at the plane image's scale), for
		// the report; the candidate's verdict when no read became a tag.
		const auto record = [&](const DecodedTag2D& d, Verdict v) {
			if (keepImages_)
			{
				out.report.decoded.push_back(d);
				out.report.readVerdicts.push_back(v);
			}
			if (v != Verdict::Decoded) reject(out.report, v);
		};
		for (DecodedTag2D& d : reads)
		{
			// libapriltag finds its own outlines, the group's earlier tags too.
			if (const auto on = earlierTagAt(plane.frame.toMap(scale * centreOf(d.corners)), earlier))
			{
				for (auto& c : d.corners) c *= scale;
				record(d, Verdict::OnDecodedTag);
				if (!out.report.onTagOf) out.report.onTagOf = on;
				continue;
			}
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
			record(d, v);
			if (v != Verdict::Decoded) continue;
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

	// A read in 3D: the size asked for, a code whose vertex order can be
	// known, pose, plane refit, the tag's own bitmap fitted to its points,
	// the refined size, the code on the cells the points measured, the
	// support plane, the side it faces. Verdict::Decoded and `t` when it
	// holds.
	Verdict verifyRead(const DecodedTag2D& d, const ReadEvidence& ev, const PlaneImage& plane, TagDetection& t) const
	{
		// A decode the size of a few points (a code read into text or a
		// corner of a bigger pattern) is no tag of the sizes asked for.
		if (!sizeAsked(measuredTagSize(d, plane))) return Verdict::SizeMismatch;
		// Its pose could be half a turn off with nothing to tell.
		if (isOwnTurnedImage(d.family, d.id)) return Verdict::TurnSymmetric;
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

	// The read's printed face looks into free space (front_side.h): a
	// sensor could see it, and the columns in front of and behind the tag,
	// a few tag sizes deep, do not say otherwise.
	bool facesFreeSpace(const TagDetection& t) const
	{
		if (!p_.frontSide.enabled) return true;
		// Lines of sight start past the voxels of the sheet's own points:
		// within the plane's noise of it, and up to a voxel diagonal beyond.
		if (seenOnlyFromBehind(t, viewpoints_, grid_, len_.planeNoise + 2 * grid_.cellSize())) return false;
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
	const VoxelGrid& grid_;
	const OctreeGatherer& gatherer_;
	const std::vector<Eigen::Vector3d>& viewpoints_;  // where the sensors stood, if known
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

}  // namespace

std::vector<TagDetection> decodeCandidates(const PipelineParams& p, const MapView& m, const VoxelGrid& grid,
										   const OctreeGatherer& gatherer, const std::vector<Eigen::Vector3d>& viewpoints,
										   const DerivedLengths& len, const std::vector<std::string>& decodedFamilies,
										   bool keepImages, const std::vector<Candidate>& candidates,
										   std::vector<CandidateReport>& reports, unsigned threads,
										   const CountProgressFn& progress,
										   const std::function<CandidateDecoders(unsigned worker)>& decodersFor)
{
	const CandidateDecoder decoder(p, m, grid, gatherer, viewpoints, len, keepImages, decodedFamilies);
	std::vector<std::vector<TagDetection>> perCandidate(candidates.size());
	std::vector<OrientedBox> boxes;
	for (const Candidate& c : candidates) boxes.push_back(c.box);
	// decode_schedule.h: a group on one worker, the candidate of the most
	// cluster points first (ties in candidate order): the cluster that
	// holds a tag's whole border before the fragments around it, which its
	// tag then spares.
	std::vector<std::vector<size_t>> groups = concentricBoxGroups(boxes);
	for (std::vector<size_t>& g : groups)
		std::stable_sort(g.begin(), g.end(), [&](size_t a, size_t b) {
			return reports[candidates[a].report].clusterPoints > reports[candidates[b].report].clusterPoints;
		});
	std::atomic<size_t> finished{0};
	parallelForWorkers(groups.size(), threads, [&](unsigned worker, size_t b, size_t e) {
		const CandidateDecoders decoders = decodersFor(worker);
		for (size_t g = b; g < e; g++)
		{
			// The tags the group's candidates decoded so far.
			EarlierTags decoded;
			for (const size_t k : groups[g])
			{
				CandidateReport& rep = reports[candidates[k].report];
				if (const std::optional<size_t> on = earlierTagAt(candidates[k].box.center, decoded))
				{
					rep.verdict = Verdict::OnDecodedTag;
					rep.onTagOf = on;
				}
				else
				{
					CandidateOutcome o =
						decoder.decodeCandidate(candidates[k], std::move(rep), decoders.hard, decoders.soft, decoded);
					rep = std::move(o.report);
					perCandidate[k] = std::move(o.tags);
					for (const TagDetection& t : perCandidate[k]) decoded.emplace_back(&t, candidates[k].report);
				}
				progress(++finished, candidates.size());
			}
		}
	});
	std::vector<TagDetection> all;
	for (auto& v : perCandidate)
		for (auto& t : v) all.push_back(std::move(t));
	return all;
}

}  // namespace tagmap::detail
