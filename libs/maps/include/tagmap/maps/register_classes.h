// Making tagmap's MRPT classes known to MRPT: the class registry (so archives
// naming tagmap::maps::CTagMap or tagmap::obs::CObservationTagPoses can be
// read back) and the [MetricMap] ini factory ("tagMap" in CMultiMetricMap
// ini files).
//
// Programs rarely call it: CTagMap.cpp and CObservationTagPoses.cpp call it
// at load time, so linking either class is enough. It is public for the case
// where a program only reads such objects by name and never names the
// classes in code (the MRPT plugin is exactly that).
#pragma once

namespace tagmap::maps
{
/** Registers CTagMap, CObservationTagPoses and the "tagMap" ini name. Safe to
 *  call any number of times, from any thread. */
void registerClasses();

}  // namespace tagmap::maps
