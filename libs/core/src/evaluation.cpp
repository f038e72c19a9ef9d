#include "tagmap/evaluation.h"

#include <algorithm>
#include <cmath>

#include "tagmap/tag_family.h"

namespace tagmap
{
int Evaluation::found() const
{
	return static_cast<int>(std::count_if(perTruth.begin(), perTruth.end(), [](const TagError& e) { return e.found; }));
}

Evaluation evaluateDetections(const std::vector<TagDetection>& found, const std::vector<TagDetection>& truth)
{
	Evaluation ev;
	std::vector<bool> used(found.size(), false);
	for (const auto& t : truth)
	{
		TagError e;
		e.family = t.family;
		e.id = t.id;
		for (size_t k = 0; k < found.size() && !e.found; k++)
		{
			const auto& d = found[k];
			if (used[k] || !sameMarker(d.family, d.id, t.family, t.id)) continue;
			if ((d.position() - t.position()).norm() > 0.5 * t.size) continue;
			used[k] = true;
			e.found = true;
			e.positionError = (d.position() - t.position()).cwiseAbs();
			e.rotationErrorDeg = (rollPitchYaw(t.pose.linear().transpose() * d.pose.linear()) * 180.0 / M_PI).cwiseAbs();
			e.vertexOrderCorrect = true;
			for (int c = 0; c < 4; c++)
			{
				e.maxCornerError = std::max(e.maxCornerError, (d.corners[c] - t.corners[c]).norm());
				for (int o = 0; o < 4; o++)
					if (o != c && (d.corners[c] - t.corners[o]).norm() < (d.corners[c] - t.corners[c]).norm())
						e.vertexOrderCorrect = false;
			}
		}
		ev.perTruth.push_back(e);
	}
	for (size_t k = 0; k < found.size(); k++)
		if (!used[k]) ev.falseDetections.push_back(found[k]);
	return ev;
}

}  // namespace tagmap
