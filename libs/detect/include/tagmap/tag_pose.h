// Stage 6 (paper, Sec. II-E, end): decoded 2D corners back to 3D on the
// fitted tag plane, in vertex-index order, and the pose T_G_tag by SVD
// (Kabsch) against the tag model, with a covariance.
#pragma once

#include <vector>

#include "tagmap/intermediate_plane.h"
#include "tagmap/tag_decoder.h"
#include "tagmap/tag_detection.h"
#include "tagmap/tag_quads.h"

namespace tagmap
{
/** The border square's mean edge in metres, from the decoded corners. */
double measuredTagSize(const DecodedTag2D& decoded, const PlaneImage& plane);
/** The same for any outline on the image (tag_quads.h). */
double measuredTagSize(const Quad& corners, const PlaneImage& plane);

/** The box a read's whole grid fits in (its family's cells beyond the
 *  border, and the quiet zone: TagBitmap::cells across), centred on the
 *  read, axes along its first edge, across it and the plane normal;
 *  no thickness (extent.z() 0). A read cut off by the image it was read
 *  from is decoded again on an image of this box. */
OrientedBox wholeGridBox(const DecodedTag2D& decoded, const PlaneImage& plane);

/** `knownSize` > 0 forces the model size; otherwise it is measured from
 *  the corners. The tag's z axis is the plane normal, oriented by the
 *  corner order (z = x_tag cross y_tag), so mirrored reads come out right. */
TagDetection solveTagPose(const DecodedTag2D& decoded, const PlaneImage& plane, double knownSize);

/** Re-fits the tag plane from the points inside the tag's own border
 *  square only, and tilts the pose onto it (keeping its in-plane position).
 *  The candidate plane also holds the surface around the tag; a tag on a
 *  board standing off a wall, or slightly tilted, would be biased towards
 *  that surface. Updates pose, corners, pointsUsed and the tilt covariance. */
void refitTagPlane(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs);

/** Covariance of [x y z | rx ry rz] in the map frame from in-plane and
 *  out-of-plane standard deviations expressed in the tag frame. */
Eigen::Matrix<double, 6, 6> tagFrameCovarianceToMap(const Eigen::Matrix3d& R_G_tag, const Eigen::Vector3d& sigmaT,
													 const Eigen::Vector3d& sigmaR);

/** Sets the covariance of some of the tag frame's axes (0: x, 1: y, 2: the
 *  normal) in the position (`rotation` false) or rotation block of `C` (map
 *  frame; R_G_tag the tag's orientation) to `block`, over `axes` in the
 *  order given. Their covariance with the other axes is dropped: it came
 *  with the estimate being replaced, and kept beside a new one it can leave
 *  C indefinite (negative variances in the JSON of 2 of 24 randomized maps
 *  before). */
void setTagFrameCovariance(Eigen::Matrix<double, 6, 6>& C, const Eigen::Matrix3d& R_G_tag, bool rotation,
						   const std::vector<int>& axes, const Eigen::MatrixXd& block);

}  // namespace tagmap
