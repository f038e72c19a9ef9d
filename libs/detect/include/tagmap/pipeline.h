// The detection pipeline: a CPointsMapXYZI in, tags with IDs, indexed
// vertices and 6-DoF poses out. It wires the stages (one file each, in this
// folder) and reports per-stage timings and counts.
//
//   mrpt::maps::CPointsMapXYZI map = tagmap::io::loadPointCloud("site.pcd");
//   tagmap::Pipeline pipeline(tagmap::PipelineParams::fromYamlFile("share/config/default.yaml"));
//   tagmap::Detections found = pipeline.detect(map);
#pragma once

#include <mrpt/containers/yaml.h>
#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tagmap/pipeline_params.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_detection.h"
#include "tagmap/verdict.h"

namespace tagmap
{
struct StageReport
{
	std::string name;  // "intensity_gradient", "clustering", ...
	double seconds = 0;
	size_t itemsIn = 0;  // points or clusters in
	size_t itemsOut = 0;  // points or clusters out
};

/** What happened to one candidate cluster (for reports and debugging). */
struct CandidateReport
{
	Eigen::Vector3d center = Eigen::Vector3d::Zero();
	Eigen::Vector3d extent = Eigen::Vector3d::Zero();  // OBB l, w, h
	size_t clusterPoints = 0;
	size_t gatheredPoints = 0;
	Verdict verdict = Verdict::Candidate;  // verdict.h: names and meanings
	// Filled only with Pipeline::detect(..., keepImages = true), for reports:
	cv::Mat image;  // the intermediate-plane intensity image
	std::vector<DecodedTag2D> decoded;  // what the decoders read on it
	/** What became of each read of `decoded`: the candidate's own verdict
	 *  is its last rejection when no read became a tag. */
	std::vector<Verdict> readVerdicts;
	std::vector<std::string> decodedLabels;  // "tag36h11:3" per accepted decode
	/** Verdict::SameBox: the index (in Detections::candidates) of the
	 *  earlier candidate with this box, which was decoded instead. */
	std::optional<size_t> sameBoxAs;
	/** The index (in Detections::candidates) of the earlier candidate that
	 *  decoded a tag this box is centred on (Verdict::OnDecodedTag), or that
	 *  its outlines or reads lay on (not decoded again; its verdict is
	 *  on_decoded_tag when it read nothing else). */
	std::optional<size_t> onTagOf;
};

struct Detections
{
	std::vector<TagDetection> tags;  // sorted by family, then id
	std::vector<StageReport> stages;
	std::vector<CandidateReport> candidates;
	double totalSeconds = 0;
	// What the map measured, that every length and tolerance derives from:
	double pointSpacing = 0;  // metres, median nearest-neighbour distance
	double surfaceNoise = 0;  // metres, median plane-fit RMS of neighbourhoods
};

namespace detail
{
struct CandidateDecoders;  // a worker's decoders (candidate_decoder.h, private)
}

/** Progress callback: stage name, items done, items total. */
using ProgressFn = std::function<void(const std::string& stage, size_t done, size_t total)>;

class Pipeline
{
   public:
	explicit Pipeline(PipelineParams params = {});
	const PipelineParams& params() const { return params_; }

	/** Finds every tag in `map` (coordinates in the map frame {G}). */
	/** `keepImages`: store each candidate's image and decodes in
	 *  Detections::candidates (for --report); costs memory on big maps. */
	Detections detect(const mrpt::maps::CPointsMapXYZI& map, const ProgressFn& progress = {},
					  bool keepImages = false) const;
	/** The same, knowing where the map's sensors stood (map frame: a
	 *  simplemap's or rawlog's observations, io::LoadReport::viewpoints): a
	 *  read whose printed face none of them could see is a mirror image
	 *  (front_side.h), even on a wall scanned from one side only. */
	Detections detect(const mrpt::maps::CPointsMapXYZI& map, const std::vector<Eigen::Vector3d>& viewpoints,
					  const ProgressFn& progress = {}, bool keepImages = false) const;

   private:
	PipelineParams params_;
	// The families decoded: those asked for (all when none) in which a read
	// can pass the chance budget at all (read_evidence.h: acceptableFamilies).
	std::vector<std::string> decodedFamilies_;
	// Decoders are costly to build (libapriltag's decode tables): one per
	// worker thread, made on first use and kept for the next detect().
	mutable std::vector<std::unique_ptr<TagDecoder>> decoders_;
	mutable std::mutex decodersMutex_;
	mutable std::vector<std::unique_ptr<SoftTagDecoder>> softDecoders_;
	mutable std::vector<std::unique_ptr<TagDecoder>> viewDecoders_;  // one, unmirrored (sensor_view.h)
	detail::CandidateDecoders decodersFor(unsigned worker) const;
	const TagDecoder& viewDecoder() const;  // reads a scan's sensor view (sensor_view.h)
};

}  // namespace tagmap
