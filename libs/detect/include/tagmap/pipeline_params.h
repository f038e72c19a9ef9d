// Every parameter of the pipeline, grouped by stage. Lengths are in point
// spacings (measured from the map) or tag cells, not metres, so defaults
// hold from sparse SLAM maps to dense terrestrial scans.
// share/config/default.yaml documents each one; load with fromYamlFile().
#pragma once

#include <mrpt/containers/yaml.h>

#include <string>
#include <vector>

#include "tagmap/candidate_filter.h"
#include "tagmap/clustering.h"
#include "tagmap/intensity_gradient.h"
#include "tagmap/intermediate_plane.h"
#include "tagmap/octree_gather.h"
#include "tagmap/pattern_refinement.h"
#include "tagmap/read_evidence.h"
#include "tagmap/sensor_view.h"
#include "tagmap/point_spacing.h"
#include "tagmap/soft_decoder.h"
#include "tagmap/front_side.h"
#include "tagmap/merge_detections.h"
#include "tagmap/support_plane.h"
#include "tagmap/tag_decoder.h"

namespace tagmap
{
/** Largest tag size accepted anywhere (metres): printed fiducials are a few
 *  decimetres; a bigger number is a unit mistake (millimetres for metres). */
constexpr double kMaxTagSize = 10.0;

struct PipelineParams
{
	std::vector<std::string> families;  // empty: every supported family
	double tagSize = 0;  // metres; 0: unknown, searched in [candidates.minTagSize, candidates.maxTagSize]
	unsigned threads = 0;  // 0: all cores

	/** Gradient neighbourhood radius, in point spacings. */
	double gradientRadiusSpacings = 2.5;

	/** Image preparations tried in order (see image_variants.h). */
	std::vector<std::string> imageVariants = {"raw", "otsu", "half_smooth"};

	PointSpacingParams spacing;
	IntensityGradientParams gradient;
	ClusteringParams clustering;
	CandidateFilterParams candidates;
	GatherParams gather;
	IntermediatePlaneParams plane;
	TagDecoderParams decoder;
	SoftDecoderParams softDecoder;
	ReadEvidenceParams evidence;
	PatternRefinementParams refinement;
	SupportPlaneParams supportPlane;
	FrontSideParams frontSide;
	MergeParams merge;
	/** Single scans in their sensor frame: candidates from the sensor's
	 *  own view instead of stages 1-3 (sensor_view.h). */
	SensorViewParams sensorView;

	/** Reads the keys present in `y` over the defaults; throws
	 *  std::invalid_argument naming an unknown key or an invalid value. */
	static PipelineParams fromYaml(const mrpt::containers::yaml& y);
	static PipelineParams fromYamlFile(const std::string& path);  // throws InputError
	mrpt::containers::yaml toYaml() const;

	/** Throws std::invalid_argument when a value is out of range. */
	void validate() const;
};

}  // namespace tagmap
