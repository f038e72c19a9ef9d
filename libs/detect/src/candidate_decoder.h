// Stages 4-6 for every candidate: gather its points, render its
// intermediate plane, decode the images, judge each read on the image and in
// the points, solve the pose. Private to tagmap_detect.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "candidate.h"
#include "map_view.h"
#include "tagmap/count_progress.h"
#include "tagmap/derived_lengths.h"
#include "tagmap/octree_gather.h"
#include "tagmap/pipeline.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/voxel_grid.h"

namespace tagmap::detail
{
/** A worker thread's own decoders. */
struct CandidateDecoders
{
	const TagDecoder& hard;
	const SoftTagDecoder& soft;
};

/** What the candidates hold, as tags: candidates of nearly one centre in
 *  groups (decode_schedule.h), each group on one worker with its own
 *  decoders (`decodersFor(worker)`), the candidate of the most cluster
 *  points first, a candidate centred on a tag its group decoded before it
 *  not decoded again; each candidate's report (`reports[candidate.report]`)
 *  says what happened. Results are stored per candidate index, so the
 *  output is the same for any thread count. `progress`: candidates done.
 *  `viewpoints`: where the map's sensors stood, if known (front_side.h:
 *  seenOnlyFromBehind(), on `grid`). */
std::vector<TagDetection> decodeCandidates(const PipelineParams& p, const MapView& m, const VoxelGrid& grid,
										   const OctreeGatherer& gatherer, const std::vector<Eigen::Vector3d>& viewpoints,
										   const DerivedLengths& len, const std::vector<std::string>& decodedFamilies,
										   bool keepImages, const std::vector<Candidate>& candidates,
										   std::vector<CandidateReport>& reports, unsigned threads,
										   const CountProgressFn& progress,
										   const std::function<CandidateDecoders(unsigned worker)>& decodersFor);

}  // namespace tagmap::detail
