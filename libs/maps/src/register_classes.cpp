#include "tagmap/maps/register_classes.h"

#include <mrpt/rtti/CObject.h>

#include "tagmap/maps/CTagMap.h"
#include "tagmap/obs/CObservationTagPoses.h"

namespace tagmap::maps
{
void registerClasses()
{
	static const bool done = [] {
		mrpt::rtti::registerClass(CLASS_ID(CTagMap));
		mrpt::rtti::registerClass(CLASS_ID(obs::CObservationTagPoses));
		// The ini name registers itself (MAP_DEFINITION_REGISTER) when
		// CTagMap_definition.cpp is linked; naming its factory here makes sure
		// a static library's linker keeps that file.
		volatile auto keepDefinition = &CTagMap::MapDefinition;
		(void)keepDefinition;
		return true;
	}();
	(void)done;
}

}  // namespace tagmap::maps
