// Running tagmap::Pipeline on CTagMap's points: the only place the plugin
// meets the detection pipeline, mapping TTagDetectionOptions onto
// PipelineParams.
#include "tagmap/maps/CTagMap.h"

#if __has_include("tagmap/pipeline_params.h")
#include "tagmap/pipeline.h"
#include "tagmap/tag_family.h"
#define TAGMAP_HAVE_PIPELINE 1
#endif

#include <stdexcept>

namespace tagmap::maps
{
void CTagMap::detectTags() const
{
#ifdef TAGMAP_HAVE_PIPELINE
	PipelineParams params = detectionOptions.configFile.empty() ? PipelineParams{}
																: PipelineParams::fromYamlFile(detectionOptions.configFile);
	if (!detectionOptions.families.empty()) params.families = parseFamilyList(detectionOptions.families);
	if (detectionOptions.tagSize > 0) params.tagSize = detectionOptions.tagSize;
	m_tags = Pipeline(params).detect(m_points).tags;
	m_tagsStale = false;
#else
	// Built before the pipeline existed: keep the tags the map was given.
	throw std::runtime_error("CTagMap: this build has no detection pipeline");
#endif
}

}  // namespace tagmap::maps
