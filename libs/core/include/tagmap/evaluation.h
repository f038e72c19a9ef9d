// Scoring detections against ground truth (simulator output): which tags
// were found, the pose errors per axis (the paper's Table 2 layout), and
// whether the vertex order is right. Used by the tests and benchmarks.
#pragma once

#include <string>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap
{
struct TagError
{
	std::string family;
	int id = -1;
	bool found = false;
	int foundIndex = -1;  // the matching detection in `found` (-1: none)
	Eigen::Vector3d positionError = Eigen::Vector3d::Zero();  // |found - true| per map axis, metres
	Eigen::Vector3d rotationErrorDeg = Eigen::Vector3d::Zero();  // |roll|, |pitch|, |yaw| of R_true^T R_found
	double maxCornerError = 0;  // metres
	bool vertexOrderCorrect = false;  // every corner k nearest to true corner k
	/** False when the truth marks the tag `expected: false` (too few points
	 *  on it to decode): missing it is no error, finding it is no false tag. */
	bool required = true;
};

/** Why a reported tag matches no true tag. */
enum class FalseKind
{
	Elsewhere,  // where no true tag is: a tag made of clutter
	WrongId,  // on a true tag's square, but another family or id
	Duplicate,  // a second report of a true tag already matched
};

struct Evaluation
{
	std::vector<TagError> perTruth;  // one per ground-truth tag, in its order
	std::vector<TagDetection> falseDetections;  // found but not in the truth
	std::vector<FalseKind> falseKinds;  // one per falseDetections entry
	int found() const;
	/** Required true tags not found. */
	int missed() const;
	int falsePositives() const { return static_cast<int>(falseDetections.size()); }
	int falseOf(FalseKind kind) const;
};

/** A detection matches a true tag of the same marker (sameMarker()) whose
 *  centre is within half its size. `required[k]` (default all true) says
 *  whether truth[k] must be found. */
Evaluation evaluateDetections(const std::vector<TagDetection>& found, const std::vector<TagDetection>& truth,
							  const std::vector<bool>& required = {});

/** The `expected` flag of each tag in a truth file's list (true when absent). */
std::vector<bool> readRequiredFlags(const std::string& path, const std::string& listKey = "tags");

/** A numeric field of each tag in a truth file's list (NaN where a tag lacks
 *  it): the conditions a simulator records per tag, e.g. `points_per_cell`,
 *  `range_min`, `incidence_deg_min`, to tell why a tag was missed. */
std::vector<double> readTruthNumbers(const std::string& path, const std::string& key,
									 const std::string& listKey = "tags");

const char* falseKindName(FalseKind kind);

}  // namespace tagmap
