// Localizer (b): no filter at all. Every scan that sees a mapped tag gives
// the sensor pose directly (tag_relocalization.h), fused over the visible
// tags; scans without a mapped tag give no pose (no odometry is used, so
// each pose is independent: a check of the detector, and an instant
// relocalization for whatever runs on top).
#pragma once

#include <vector>

#include "tagmap/localize/localization_steps.h"
#include "tagmap/localize/tag_relocalization.h"
#include "tagmap/localize/trajectory_tum.h"

namespace tagmap::localize
{
struct DirectResult
{
	Trajectory trajectory;  // one pose per step with a fix
	std::vector<PoseWithCovariance> estimates;  // the same, with covariances
	std::vector<size_t> tagsUsed;  // per pose
	size_t steps = 0;  // steps run (with or without a fix)
};

DirectResult runDirectLocalization(const std::vector<TagDetection>& mapTags,
								   const std::vector<LocalizationStep>& steps,
								   const RelocalizationParams& params = {});

}  // namespace tagmap::localize
