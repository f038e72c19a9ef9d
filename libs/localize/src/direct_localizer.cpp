#include "tagmap/localize/direct_localizer.h"

namespace tagmap::localize
{
DirectResult runDirectLocalization(const std::vector<TagDetection>& mapTags,
								   const std::vector<LocalizationStep>& steps, const RelocalizationParams& params)
{
	DirectResult r;
	r.steps = steps.size();
	for (const LocalizationStep& s : steps)
	{
		size_t used = 0;
		const auto fix = relocalize(mapTags, s.tags->tags, params, &used);
		if (!fix) continue;
		r.trajectory.push_back({s.stamp, fix->pose});
		r.estimates.push_back(*fix);
		r.tagsUsed.push_back(used);
	}
	return r;
}

}  // namespace tagmap::localize
