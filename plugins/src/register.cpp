// Runs when the plugin is loaded (dlopen by RawLogViewer -l, or at program
// start when linked): MRPT deserializes objects by class name, so CTagMap must
// be in MRPT's class registry before any archive naming it is read. (The
// [MetricMap] factory name registers itself through MAP_DEFINITION_REGISTER
// in CTagMap_definition.cpp.)
#include <mrpt/core/initializer.h>

#include "tagmap/maps/CTagMap.h"
#include "tagmap/obs/CObservationTagPoses.h"

MRPT_INITIALIZER(tagmap_register_mrpt_classes)
{
	mrpt::rtti::registerClass(CLASS_ID(tagmap::maps::CTagMap));
	mrpt::rtti::registerClass(CLASS_ID(tagmap::obs::CObservationTagPoses));
}
