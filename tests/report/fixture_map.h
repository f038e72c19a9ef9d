// The map the report tests run on when no simulated scene is at hand: two
// synthetic walls at an angle, each with a tag of another family, so the
// report has two detections, several candidates and a non-trivial view.
#pragma once

#include "../unit/synthetic_wall.h"

namespace tagmap::testing
{
inline mrpt::maps::CPointsMapXYZI makeReportFixtureMap(std::vector<TagDetection>* truths = nullptr)
{
	mrpt::maps::CPointsMapXYZI map;
	WallScene a, b;
	a.T_G_wall.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();  // vertical, faces -y
	a.T_G_wall.translation() = Eigen::Vector3d(0, 2, 1);
	b = a;
	b.family = "aruco_6x6_250";
	b.id = 3;
	b.seed = 2;
	b.T_G_wall.translation() = Eigen::Vector3d(1.0, 2, 1);
	for (const WallScene* s : {&a, &b})
	{
		TagDetection truth;
		const auto wall = makeWall(*s, truth);
		map.insertAnotherMap(&wall, mrpt::poses::CPose3D());
		if (truths) truths->push_back(truth);
	}
	return map;
}

}  // namespace tagmap::testing
