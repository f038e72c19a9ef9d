#include "synthetic_tags.h"

#include "tagmap/tag_family.h"

namespace tagmap::mrpt_test
{
namespace
{
TagDetection tagOnWall(const std::string& family, int id, double size, double y, double z)
{
	TagDetection t;
	t.family = family;
	t.id = id;
	t.size = size;
	// Facing the origin: z_tag = -x_G; upright, so y_tag = +z_G; x_tag = y_tag x z_tag.
	Eigen::Matrix3d R;
	R.col(0) = Eigen::Vector3d(0, -1, 0);
	R.col(1) = Eigen::Vector3d(0, 0, 1);
	R.col(2) = Eigen::Vector3d(-1, 0, 0);
	t.pose.linear() = R;
	t.pose.translation() = Eigen::Vector3d(5.0, y, z);
	t.corners = cornersFromPose(t.pose, size);
	t.covariance.diagonal() << 1e-4, 2e-4, 3e-4, 1e-3, 2e-3, 3e-3;
	return t;
}
}  // namespace

std::vector<TagDetection> syntheticTags()
{
	return {tagOnWall("tag36h11", 3, 0.5, 1.0, 1.2), tagOnWall("tag36h11", 7, 0.5, -0.5, 1.0),
			tagOnWall("aruco_4x4_50", 3, 0.4, -1.8, 1.4)};
}

mrpt::maps::CPointsMapXYZI syntheticWallMap(const std::vector<TagDetection>& tags)
{
	mrpt::maps::CPointsMapXYZI map;
	const double step = 0.02;
	for (double y = -3; y <= 3; y += step)
		for (double z = 0; z <= 2.5; z += step)
		{
			float intensity = 120;
			const Eigen::Vector3d p(5.0, y, z);
			for (const auto& t : tags)
			{
				const Eigen::Vector3d q = t.pose.inverse() * p;  // in the tag frame
				const TagBitmap bmp = renderTagBitmap(t.family, t.id);
				const double cell = t.size / bmp.borderCells;
				const int col = static_cast<int>(std::floor(q.x() / cell + bmp.borderStart + 0.5 * bmp.borderCells));
				const int row = static_cast<int>(std::floor(-q.y() / cell + bmp.borderStart + 0.5 * bmp.borderCells));
				if (row >= 0 && col >= 0 && row < bmp.cells && col < bmp.cells) intensity = bmp.at(row, col);
			}
			map.insertPointFast(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
			map.setPointIntensity(map.size() - 1, intensity);
		}
	return map;
}

}  // namespace tagmap::mrpt_test
