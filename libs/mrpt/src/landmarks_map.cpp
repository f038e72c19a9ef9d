#include "tagmap/mrpt/landmarks_map.h"

#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/serialize_gz.h"

namespace tagmap::mrpt_bridge
{
// A detection without a covariance (e.g. synthetic ground truth) would give
// a singular landmark PDF; MRPT's own ini loader uses this same 1 cm floor.
constexpr float kMinPositionVariance = 0.01f * 0.01f;

mrpt::maps::CLandmark tagToLandmark(const TagDetection& tag)
{
	mrpt::maps::CLandmark lm;
	const auto beaconId = encodeBeaconId(tag.family, tag.id);
	lm.createOneFeature();
	lm.features[0].type = mrpt::vision::featBeacon;
	lm.features[0].keypoint.ID = static_cast<mrpt::vision::TFeatureID>(beaconId);
	lm.ID = beaconId;

	const Eigen::Vector3d c = tag.position();
	lm.pose_mean = {c.x(), c.y(), c.z()};
	const Eigen::Vector3d n = tag.pose.linear().col(2);
	lm.normal = {n.x(), n.y(), n.z()};

	const auto& P = tag.covariance;
	const bool hasCov = P.topLeftCorner<3, 3>().diagonal().minCoeff() > 0;
	lm.pose_cov_11 = hasCov ? static_cast<float>(P(0, 0)) : kMinPositionVariance;
	lm.pose_cov_22 = hasCov ? static_cast<float>(P(1, 1)) : kMinPositionVariance;
	lm.pose_cov_33 = hasCov ? static_cast<float>(P(2, 2)) : kMinPositionVariance;
	lm.pose_cov_12 = hasCov ? static_cast<float>(P(0, 1)) : 0.f;
	lm.pose_cov_13 = hasCov ? static_cast<float>(P(0, 2)) : 0.f;
	lm.pose_cov_23 = hasCov ? static_cast<float>(P(1, 2)) : 0.f;
	return lm;
}

mrpt::maps::CLandmarksMap tagsToLandmarksMap(const std::vector<TagDetection>& tags)
{
	mrpt::maps::CLandmarksMap map;
	for (const auto& tag : tags) map.landmarks.push_back(tagToLandmark(tag));
	return map;
}

void writeLandmarksMap(const std::string& path, const std::vector<TagDetection>& tags)
{
	writeSerializableGz(path, tagsToLandmarksMap(tags));
}

}  // namespace tagmap::mrpt_bridge
