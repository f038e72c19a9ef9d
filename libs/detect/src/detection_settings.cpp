#include "tagmap/detection_settings.h"

#include "tagmap/tag_family.h"

namespace tagmap
{
PipelineParams resolveDetectionSettings(const DetectionChoices& choices, const PipelineParams& defaults)
{
	PipelineParams p = choices.configFile.empty() ? defaults : PipelineParams::fromYamlFile(choices.configFile);
	if (!choices.families.empty()) p.families = parseFamilyList(choices.families);
	if (choices.tagSize != 0) p.tagSize = choices.tagSize;
	if (choices.threads != 0) p.threads = choices.threads;
	p.validate();
	return p;
}

}  // namespace tagmap
