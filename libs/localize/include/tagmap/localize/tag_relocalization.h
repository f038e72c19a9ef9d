// Direct relocalization from tags: a tag whose map pose T_G_tag is known and
// which a scan sees at T_sensor_tag gives the sensor pose
//     T_G_sensor = T_G_tag * T_sensor_tag^-1
// with first-order propagated covariance. Several visible tags are fused by
// their information (covariance-weighted mean on SE(3)).
//
// Covariances follow TagDetection: [x y z | rx ry rz], translation added,
// rotation as a small-angle vector applied on the left in the frame the pose
// maps into ({G} for T_G_*, the sensor frame for T_sensor_tag).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::localize
{
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct PoseWithCovariance
{
	Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
	Matrix6d covariance = Matrix6d::Identity();
};

struct RelocalizationParams
{
	/** Map tags without a covariance (a JSON result has none) are taken as
	 *  this uncertain: a detected map tag is good to a few mm and tenths of
	 *  a degree (docs/ACCURACY). Metres, degrees. */
	double mapTagStdPosition = 0.005;
	double mapTagStdRotationDeg = 0.3;
	/** Floors on a seen tag's standard deviations: a covariance from few
	 *  points can be overconfident, and a zero one would make fusion trust a
	 *  single tag absolutely. Metres, degrees. */
	double minSeenStdPosition = 0.002;
	double minSeenStdRotationDeg = 0.1;
	int fusionIterations = 4;  // Gauss-Newton steps of the weighted mean; 2-3 suffice
};

/** T_G_sensor from one tag: `mapTag.pose` = T_G_tag, `seen.pose` = T_sensor_tag. */
PoseWithCovariance sensorPoseFromTag(const TagDetection& mapTag, const TagDetection& seen,
									 const RelocalizationParams& params = {});

/** Information-weighted mean of poses of the same frame; nullopt if empty. */
std::optional<PoseWithCovariance> fusePoses(const std::vector<PoseWithCovariance>& poses, int iterations = 4);

/** Every seen tag that is in the map (same family and id) gives a pose; all
 *  are fused. nullopt when none is in the map. `used` (optional) gets the
 *  number of tags fused. */
std::optional<PoseWithCovariance> relocalize(const std::vector<TagDetection>& map,
											 const std::vector<TagDetection>& seen,
											 const RelocalizationParams& params = {}, size_t* used = nullptr);

}  // namespace tagmap::localize
