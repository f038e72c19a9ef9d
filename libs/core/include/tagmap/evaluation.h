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
	Eigen::Vector3d positionError = Eigen::Vector3d::Zero();  // |found - true| per map axis, metres
	Eigen::Vector3d rotationErrorDeg = Eigen::Vector3d::Zero();  // |roll|, |pitch|, |yaw| of R_true^T R_found
	double maxCornerError = 0;  // metres
	bool vertexOrderCorrect = false;  // every corner k nearest to true corner k
};

struct Evaluation
{
	std::vector<TagError> perTruth;  // one per ground-truth tag, in its order
	std::vector<TagDetection> falseDetections;  // found but not in the truth
	int found() const;
	int missed() const { return static_cast<int>(perTruth.size()) - found(); }
	int falsePositives() const { return static_cast<int>(falseDetections.size()); }
};

/** A detection matches a true tag of the same marker (sameMarker()) whose
 *  centre is within half its size. */
Evaluation evaluateDetections(const std::vector<TagDetection>& found, const std::vector<TagDetection>& truth);

}  // namespace tagmap
