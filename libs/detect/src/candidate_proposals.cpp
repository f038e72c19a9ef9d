#include "candidate_proposals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "tagmap/tag_family.h"
#include "tagmap/voxel_grid.h"

namespace tagmap::detail
{
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

size_t splitClusters(const MapView& m, const IntensityGradientResult& edges, const DerivedLengths& len,
					 const PipelineParams& p, std::vector<Cluster>& clusters)
{
	const CandidateFilterParams cf = filterParams(p);
	const std::vector<uint32_t>& kept = edges.keptPoints;
	const double largestTag = cf.tagSize > 0 ? cf.tagSize : cf.maxTagSize;
	std::vector<uint32_t> significant, strong;
	for (size_t k = 0, before = clusters.size(); k < before; k++)
	{
		const Cluster& c = clusters[k];
		// (With no point kept by chance, the significant ones are the cluster again.)
		if (!edges.keptByChance.empty() && tooLargeForATag(c.box, len.candidateBand, cf))
			for (uint32_t i : c.points)
				if (!std::binary_search(edges.keptByChance.begin(), edges.keptByChance.end(), i)) significant.push_back(i);
		// A box with a diagonal no larger than the largest tag's may be the
		// tag itself; on a larger one the tag, if any, is a part of it.
		if (std::hypot(c.box.extent.x(), c.box.extent.y()) <= std::sqrt(2.0) * largestTag) continue;
		const size_t strongBefore = strong.size();
		for (uint32_t i : c.points)
			if (edges.keptStrength[std::lower_bound(kept.begin(), kept.end(), i) - kept.begin()] >=
				IntensityGradientResult::kRaisedStrength)
				strong.push_back(i);
		// Most of it above the raised bar: high-contrast clutter (a facade's
		// windows), not a wall of stripes or noise; its strong points would
		// cluster into much the same boxes again, decoded for nothing.
		if (2 * (strong.size() - strongBefore) > c.points.size()) strong.resize(strongBefore);
	}
	size_t count = 0;
	for (std::vector<uint32_t>* v : {&significant, &strong})
	{
		std::sort(v->begin(), v->end());
		v->erase(std::unique(v->begin(), v->end()), v->end());
		addClusters(m, *v, 1.0, len.spacing, p.clustering, clusters);
		count += v->size();
	}
	return count;
}

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

namespace
{
// The candidates proposed so far, by their centres' cells of one point
// spacing: a box another candidate already has, to within a spacing,
// gathers the same points into the same image and is decoded once. Its
// equal's centre is in its own cell or a neighbour (a city has thousands
// of candidates).
class ProposedBoxes
{
   public:
	explicit ProposedBoxes(double spacing) : spacing_(spacing) {}

	void add(const Candidate& c) { byCell_[cellOf(c.box.center)].push_back(c); }

	/** The report index of a candidate with `box` (sameBox()), if any. */
	std::optional<size_t> reportWith(const OrientedBox& box) const
	{
		const Cell c = cellOf(box.center);
		for (int64_t dx = -1; dx <= 1; dx++)
			for (int64_t dy = -1; dy <= 1; dy++)
				for (int64_t dz = -1; dz <= 1; dz++)
				{
					const auto it = byCell_.find({c[0] + dx, c[1] + dy, c[2] + dz});
					if (it == byCell_.end()) continue;
					for (const Candidate& o : it->second)
						if (sameBox(o.box, box, spacing_)) return o.report;
				}
		return std::nullopt;
	}

   private:
	using Cell = std::array<int64_t, 3>;
	Cell cellOf(const Eigen::Vector3d& p) const
	{
		const Eigen::Vector3d c = (p / spacing_).array().floor();
		return {static_cast<int64_t>(c.x()), static_cast<int64_t>(c.y()), static_cast<int64_t>(c.z())};
	}
	double spacing_;
	std::map<Cell, std::vector<Candidate>> byCell_;
};
}  // namespace

std::vector<Candidate> proposeCandidates(const MapView& m, const std::vector<Cluster>& clusters,
										 const CandidateFilterParams& cf, const DerivedLengths& len,
										 std::vector<CandidateReport>& reports)
{
	std::vector<Candidate> candidates;
	ProposedBoxes proposed(len.spacing);
	const auto propose = [&](const OrientedBox& box) {
		candidates.push_back({reports.size() - 1, box, std::nullopt, false});
		proposed.add(candidates.back());
	};
	for (const Cluster& c : clusters)
	{
		std::optional<Verdict> why = rejectCandidate(c.box, len.candidateBand, len.planeNoise, cf);
		CandidateReport rep;
		if (!why) rep.sameBoxAs = proposed.reportWith(c.box);
		if (rep.sameBoxAs) why = Verdict::SameBox;
		rep.center = c.box.center;
		rep.extent = c.box.extent;
		rep.clusterPoints = c.points.size();
		rep.verdict = why.value_or(Verdict::Candidate);
		reports.push_back(rep);
		if (!why) propose(c.box);
		if (why != Verdict::Squareness) continue;
		std::vector<double> along;
		for (uint32_t i : c.points) along.push_back((m.point(i) - c.box.center).dot(c.box.axes.col(0)));
		for (const OrientedBox& w : squareWindows(c.box, len.candidateBand, len.planeNoise, cf, along))
		{
			rep.center = w.center;
			rep.extent = w.extent;
			rep.sameBoxAs = proposed.reportWith(w);
			rep.verdict = rep.sameBoxAs ? Verdict::SameBox : Verdict::Candidate;
			reports.push_back(rep);
			if (!rep.sameBoxAs) propose(w);
		}
	}
	return candidates;
}

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
	// The view proposes boxes for its reads; on its many quads the soft
	// decoder leaves the families with white border rings to libapriltag
	// (SoftTagDecoder::decode).
	for (DecodedTag2D& d : soft.decode(out.view.gray, quads, nullptr, false)) out.reads.push_back(std::move(d));
	return out;
}

std::vector<Candidate> proposeFromSensorView(const MapView& m, const SensorViewReads& seen,
											 const std::vector<uint32_t>& near, const PipelineParams& p,
											 const DerivedLengths& len, std::vector<CandidateReport>& reports)
{
	std::vector<Candidate> candidates;
	const CandidateFilterParams cf = filterParams(p);
	for (const DecodedTag2D& d : seen.reads)
	{
		OrientedBox box;
		std::array<Eigen::Vector3d, 4> corners;
		if (!boxOfRead(seen.view, d, m.xs, m.ys, m.zs, near, len.candidateBand, box, &corners)) continue;
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
		if (!why) candidates.push_back({reports.size() - 1, box, corners, aprilTag});
	}
	return candidates;
}

}  // namespace tagmap::detail
