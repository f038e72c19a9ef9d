// The [MetricMap] ini factory for CTagMap: "tagMap_count=1" plus sections
// <prefix>_creationOpts (tags, generic map params), _detectionOpts,
// _likelihoodOpts and _visualOpts. Registered under both the C++ name and
// the short name "tagMap", like MRPT's own maps ("landmarksMap", ...).
#include <mrpt/config/CConfigFileBase.h>

#include "tagmap/detection_settings.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/tags_ini.h"
#include "tagmap/tag_family.h"

MAP_DEFINITION_REGISTER("tagmap::maps::CTagMap,tagMap", tagmap::maps::CTagMap)

namespace tagmap::maps
{
CTagMap::TMapDefinition::TMapDefinition() = default;

void CTagMap::TMapDefinition::loadFromConfigFile_map_specific(const mrpt::config::CConfigFileBase& source,
															  const std::string& prefix)
{
	initialTags = mrpt_bridge::readTagsIniKeys(source, prefix + "_creationOpts");
	detectionOpts.loadFromConfigFile(source, prefix + "_detectionOpts");
	likelihoodOpts.loadFromConfigFile(source, prefix + "_likelihoodOpts");
	visualOpts.loadFromConfigFile(source, prefix + "_visualOpts");
	// Fail at load time, not at the first detection, on a misspelt family.
	if (!detectionOpts.families.empty()) parseFamilyList(detectionOpts.families);
}

void CTagMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const
{
	out << "initial tags                            = " << initialTags.size() << "\n";
	detectionOpts.dumpToTextStream(out);
	likelihoodOpts.dumpToTextStream(out);
	visualOpts.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CTagMap::internal_CreateFromMapDefinition(const mrpt::maps::TMetricMapInitializer& def_)
{
	const auto& def = dynamic_cast<const CTagMap::TMapDefinition&>(def_);
	auto* map = new CTagMap();
	map->detectionParams = resolveDetectionSettings(detectionChoices(def.detectionOpts));
	map->likelihoodOptions = def.likelihoodOpts;
	map->visualOptions = def.visualOpts;
	map->setTags(def.initialTags);
	return map;
}

}  // namespace tagmap::maps
