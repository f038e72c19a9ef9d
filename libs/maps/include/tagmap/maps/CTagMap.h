// tagmap::maps::CTagMap: a map of fiducial tags as a first-class MRPT metric
// map. It lives in tagmap_maps (libs/maps); linking it registers the class
// for deserialization and the name "tagMap" for [MetricMap] ini files
// (register_classes.h). MRPT's own apps get it by loading the plugin
// (RawLogViewer -l libtagmap_mrpt_plugin.so).
//
//  - insertObservation(): LiDAR observations with intensity accumulate points;
//    tags are detected on demand (tags()) by tagmap::Pipeline.
//  - computeObservationLikelihood(): CObservationBeaconRanges against the tag
//    centres, beacon IDs as in tagmap/mrpt/beacon_id.h (as CLandmarksMap does);
//    CObservationTagPoses by each seen tag's 6-DoF pose against the mapped
//    tag (robust Gaussian, CTagMap_likelihood.cpp).
//  - getVisualizationInto(): tags with their real bitmaps, labels, axes, and
//    optionally the points coloured by intensity.
//  - asString(): a table family / id / size / position / roll-pitch-yaw.
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>
#include <vector>

#include "tagmap/maps/tag_map_options.h"
#include "tagmap/obs/CObservationTagPoses.h"
#include "tagmap/pipeline_params.h"
#include "tagmap/tag_detection.h"

namespace tagmap::maps
{
class CTagMap : public mrpt::maps::CMetricMap
{
	DEFINE_SERIALIZABLE(CTagMap, tagmap::maps)

   public:
	CTagMap() = default;

	/** The detection settings tags() re-detects with, resolved when the map
	 *  was made (resolveDetectionSettings: defaults, config file, choices) and
	 *  stored whole, so the map detects the same way on any machine. */
	PipelineParams detectionParams;
	TTagLikelihoodOptions likelihoodOptions;
	TTagVisualOptions visualOptions;

	/** The tags; runs detection first if points were inserted since the last
	 *  detection (so it may take a while on a large map). */
	const std::vector<TagDetection>& tags() const;

	/** Replaces the tags (e.g. with a `tagmap detect` result). */
	void setTags(std::vector<TagDetection> tags);

	/** Points accumulated by insertObservation(), in the map frame. */
	const mrpt::maps::CPointsMapXYZI& points() const { return m_points; }
	/** Where the sensor stood for each observation inserted (map frame):
	 *  detection rejects a read whose printed face none of them could see
	 *  (front_side.h), as `tagmap detect` does on a simplemap or rawlog. */
	const std::vector<Eigen::Vector3d>& viewpoints() const { return m_viewpoints; }
	void setPoints(const mrpt::maps::CPointsMapXYZI& points, const std::vector<Eigen::Vector3d>& viewpoints = {});

	/** Runs detection on the accumulated points now. */
	void detectTags() const;

	// CMetricMap
	bool isEmpty() const override;
	/** Writes <prefix>_tags.json (docs/RESULT_FORMAT.md). */
	void saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const override;
	// Visualizable
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
	// Stringifyable
	std::string asString() const override;

	MAP_DEFINITION_START(CTagMap)
	std::vector<TagDetection> initialTags;  // "<prefix>_creationOpts": tag_count, tag_%03u_* (tagmap/mrpt/tags_ini.h)
	TTagDetectionOptions detectionOpts;  // "<prefix>_detectionOpts", resolved into detectionParams
	TTagLikelihoodOptions likelihoodOpts;  // "<prefix>_likelihoodOpts"
	TTagVisualOptions visualOpts;  // "<prefix>_visualOpts"
	MAP_DEFINITION_END(CTagMap)

   private:
	mrpt::maps::CPointsMapXYZI m_points;
	std::vector<Eigen::Vector3d> m_viewpoints;
	// Detection is lazy, so a const map can still bring its tags up to date.
	mutable std::vector<TagDetection> m_tags;
	mutable bool m_tagsStale = false;
	// encodeBeaconId of each tag, for the range likelihood (a family lookup
	// per tag, particle and range made the demo's range-only PF 4.6 s instead
	// of 1.9 s). Cleared wherever m_tags is replaced; rebuilt on demand.
	mutable std::vector<int64_t> m_beaconIds;
	const std::vector<int64_t>& beaconIds() const;

	void internal_clear() override;
	bool internal_insertObservation(const mrpt::obs::CObservation& obs,
									const std::optional<const mrpt::poses::CPose3D>& robotPose) override;
	double internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
												 const mrpt::poses::CPose3D& takenFrom) const override;
	bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const override;
	double tagPosesLogLikelihood(const obs::CObservationTagPoses& o, const mrpt::poses::CPose3D& robotPose) const;
};

}  // namespace tagmap::maps
