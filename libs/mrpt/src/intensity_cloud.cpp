#include "tagmap/quantile.h"
#include "tagmap/mrpt/intensity_cloud.h"

#include <mrpt/core/format.h>
#include <mrpt/img/color_maps.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tagmap/mrpt/tag_visual.h"

namespace tagmap::mrpt_bridge
{
namespace
{
std::pair<float, float> percentileRange(const mrpt::aligned_std_vector<float>& values)
{
	if (values.empty()) return {0.f, 1.f};
	std::vector<float> v(values.begin(), values.end());
	const float lo = quantileInPlace(v, 0.01), hi = quantileInPlace(v, 0.99);
	return {lo, hi > lo ? hi : lo + 1.f};
}

// The boxes around drawn tag patterns, as tag-frame transforms and extents.
struct HiddenBox
{
	Eigen::Isometry3d mapToTag;
	double halfSide;
	bool contains(const Eigen::Vector3d& p) const
	{
		const Eigen::Vector3d q = mapToTag * p;
		return std::abs(q.x()) <= halfSide && std::abs(q.y()) <= halfSide && std::abs(q.z()) <= 0.1;
	}
};
}  // namespace

mrpt::opengl::CPointCloudColoured::Ptr makeIntensityCloud(const mrpt::maps::CPointsMapXYZI& map,
														   const IntensityCloudParams& params,
														   const std::vector<TagDetection>& drawnOver)
{
	std::vector<HiddenBox> hidden;
	for (const auto& t : drawnOver) hidden.push_back({t.pose.inverse(), drawnHalfSide(t)});

	auto cloud = mrpt::opengl::CPointCloudColoured::Create();
	cloud->setPointSize(params.pointSize);
	if (!params.localOrigin.isZero())
		cloud->setName(mrpt::format("map (local frame: file = local + (%.3f, %.3f, %.3f) m)", params.localOrigin.x(),
									params.localOrigin.y(), params.localOrigin.z()));
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	const auto& zs = map.getPointsBufferRef_z();
	const auto& is = map.getPointsBufferRef_intensity();
	const size_t n = xs.size();
	const size_t step = params.maxPoints > 0 ? std::max<size_t>(1, (n + params.maxPoints - 1) / params.maxPoints) : 1;
	const auto [lo, hi] = percentileRange(is);
	for (size_t i = 0; i < n; i += step)
	{
		const Eigen::Vector3d p(xs[i], ys[i], zs[i]);
		if (std::any_of(hidden.begin(), hidden.end(), [&](const HiddenBox& b) { return b.contains(p); })) continue;
		const float t = std::clamp((is[i] - lo) / (hi - lo), 0.f, 1.f);
		float r, g, b;
		mrpt::img::jet2rgb(t, r, g, b);
		cloud->push_back(xs[i], ys[i], zs[i], r, g, b);
	}
	return cloud;
}

}  // namespace tagmap::mrpt_bridge
