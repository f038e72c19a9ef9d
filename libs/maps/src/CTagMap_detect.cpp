// Running tagmap::Pipeline on CTagMap's points: the only place the plugin
// meets the detection pipeline, mapping TTagDetectionOptions onto
// PipelineParams.
#include "tagmap/maps/CTagMap.h"
#include "tagmap/pipeline.h"
#include "tagmap/tag_family.h"

namespace tagmap::maps
{
void CTagMap::detectTags() const
{
	PipelineParams params = detectionOptions.configFile.empty() ? PipelineParams{}
																: PipelineParams::fromYamlFile(detectionOptions.configFile);
	if (!detectionOptions.families.empty()) params.families = parseFamilyList(detectionOptions.families);
	if (detectionOptions.tagSize > 0) params.tagSize = detectionOptions.tagSize;
	m_tags = Pipeline(params).detect(m_points).tags;
	m_tagsStale = false;
}

}  // namespace tagmap::maps
