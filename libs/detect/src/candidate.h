// What the stages that propose candidates (1-3) hand to those that decode
// them (4-6), and what both read of the detection asked for: the families,
// the sizes, the orientations. Private to tagmap_detect.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "tagmap/candidate_filter.h"
#include "tagmap/clustering.h"
#include "tagmap/pipeline_params.h"

namespace tagmap::detail
{
/** How far a decoded square's edge may be from --tag-size: corners on a
 *  blurred image are a pixel or two off, a code read into a pattern twice
 *  or half the size is no tag. */
constexpr double kGivenSizeTolerance = 0.3;

// A candidate: the box to gather around, and the report it fills in.
struct Candidate
{
	size_t report;  // into Detections::candidates
	OrientedBox box;
	/** Proposed by a read of the scan's sensor view: the read's corners on
	 *  the tag's plane (boxOfRead()), where the candidate image is read
	 *  first. */
	std::optional<std::array<Eigen::Vector3d, 4>> cornersInView;
	/** That read was libapriltag's: its image is then read by it next,
	 *  before any clutter test. */
	bool aprilTagInView = false;
};

/** The candidate filter as asked: --tag-size, when given, is the only size. */
CandidateFilterParams filterParams(const PipelineParams& p);

/** The fewest and the most cells across a border square among `families`
 *  (aruco_4x4: 6, aruco_7x7: 9); both 0 when there are none. */
struct BorderCellsRange
{
	int fewest = 0, most = 0;
};
BorderCellsRange borderCellsAcross(const std::vector<std::string>& families);

/** The families a detection searches (all of them when none are named). */
std::vector<std::string> familiesAsked(const PipelineParams& p);

/** The smallest border square a detection can report: --tag-size less its
 *  tolerance, else candidates.min_tag_size. */
double smallestSideAsked(const PipelineParams& p);

/** The smallest cell of any tag a detection can report: the smallest size
 *  asked for over the most cells across a border square of the families
 *  decoded (aruco_7x7: 9); 0 when none. The images need not resolve anything
 *  finer (IntermediatePlaneParams::pixelsPerCell). Not the smallest the
 *  box's size implies: tags far smaller than their box are found too (a
 *  0.17 m tag in a 3 m window of a sparse wall). */
double smallestReportableCell(const PipelineParams& p, const std::vector<std::string>& families);

/** The orientations each quad is read in: 4 rotations, each also mirrored. */
int readOrientations(const PipelineParams& p);

}  // namespace tagmap::detail
