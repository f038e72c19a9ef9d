#include "tagmap/local_frame.h"

namespace tagmap
{
std::vector<TagDetection> translatedTags(std::vector<TagDetection> tags, const Eigen::Vector3d& offset)
{
	for (auto& t : tags)
	{
		t.pose.translation() += offset;
		for (auto& c : t.corners) c += offset;
	}
	return tags;
}

}  // namespace tagmap
