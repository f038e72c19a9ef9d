// Stages 1-3 after the gradient: the candidates a map's clusters or a
// scan's own sensor view propose, each with its report. Private to
// tagmap_detect; the pipeline (pipeline.cpp) runs them as its stages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "candidate.h"
#include "map_view.h"
#include "tagmap/derived_lengths.h"
#include "tagmap/intensity_gradient.h"
#include "tagmap/pipeline.h"
#include "tagmap/sensor_view.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/tag_decoder.h"

namespace tagmap::detail
{
/** A scan's view and what the decoders read in it (sensor_view.h). */
struct SensorViewReads
{
	SensorView view;
	std::vector<DecodedTag2D> reads;
};

// Clusters at several tolerances: the point spacing varies across a map
// (near and far views, overlapping passes), and a tag scanned more sparsely
// than the map's median breaks into fragments at the finest tolerance. A
// coarser one re-joins it; identical clusters are kept once. `levelScale`:
// the density level's radius multiple (1, 3, 9 ...). Returns the clusters
// in all.
size_t addClusters(const MapView& m, const std::vector<uint32_t>& kept, double levelScale, double spacing,
				   const ClusteringParams& p, std::vector<Cluster>& clusters);

// A plain wall can pass the gradient's fixed bars all over (range noise
// thicker than r, strong intensity noise, intensity stripes of a surface
// scanned from many ranges) and cluster whole with a tag on it. Two splits
// let the tag's edges stand apart:
//  - a cluster too large for any tag asked for is clustered again on its
//    points that beat chance (IntensityGradientResult::keptByChance);
//  - a cluster wider than the largest tag's diagonal whose points mostly
//    stay under the raised bar (stripes, noise) is clustered again on
//    those that clear it (keptStrength, kRaisedStrength): a black-white
//    edge does. A cluster mostly above it (a facade's windows) would only
//    give its own boxes again.
// New clusters are added; none is removed, so no candidate of today is
// lost. Returns the points re-clustered.
size_t splitClusters(const MapView& m, const IntensityGradientResult& edges, const DerivedLengths& len,
					 const PipelineParams& p, std::vector<Cluster>& clusters);

// Density levels: where the map is sparser than its median (far from the
// sensor, a fast pass), a point has too few neighbours within r to fit a
// gradient. Those points alone are run again at 3x the radius and clustered
// at 3x the tolerance, and so on, so the result follows the local spacing,
// not the map's densest part. Adds to `clusters`; returns the points kept.
size_t clusterSparseLevels(const MapView& m, IntensityGradientResult level, const DerivedLengths& len,
						   const PipelineParams& p, unsigned threads, std::vector<Cluster>& clusters);

// Stage 3 over every cluster: a report each, and the boxes that may hold a
// tag: the cluster's own, or for a box too long for a tag (maybe a tag
// clustered together with an edge beside it: a pillar's corner, a shelf)
// its square windows, candidates of their own. A box an earlier candidate
// already has (sameBox() within a point spacing: clusters of the same points
// at two tolerances or density levels) is reported as same_box, not decoded
// again.
std::vector<Candidate> proposeCandidates(const MapView& m, const std::vector<Cluster>& clusters,
										 const CandidateFilterParams& cf, const DerivedLengths& len,
										 std::vector<CandidateReport>& reports);

// Stages 1-3 for a scan in its sensor frame (sensor_view.h), first half:
// the scan as its sensor sees it and every read of it, by libapriltag and
// by the soft decoder. Needs none of the scan's measured lengths.
SensorViewReads readSensorView(const MapView& m, const PipelineParams& p, const std::vector<std::string>& families,
							   const TagDecoder& hard, const SoftTagDecoder& soft);

// Second half: the box around each read's corners (from the scan's points
// `near` the reads); reads of one quad (plain and mirrored, hard and soft)
// propose it once. Each box passes the same size, squareness and flatness
// criteria as a cluster's.
std::vector<Candidate> proposeFromSensorView(const MapView& m, const SensorViewReads& seen,
											 const std::vector<uint32_t>& near, const PipelineParams& p,
											 const DerivedLengths& len, std::vector<CandidateReport>& reports);

}  // namespace tagmap::detail
