// Accumulating LiDAR observations into CTagMap's point map, converted exactly
// as tagmap's own readers convert them (tagmap::io::appendObservationToMap),
// so a map built in an MRPT app and one loaded by `tagmap detect` agree.
// Tags are not detected per observation (a tag is rarely complete in one
// scan); the map marks its tags stale and tags() re-detects on demand.
#include "tagmap/io/mrpt_observations.h"
#include "tagmap/maps/CTagMap.h"

namespace tagmap::maps
{
bool CTagMap::internal_insertObservation(const mrpt::obs::CObservation& obs,
										 const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	io::LoadReport report;
	if (!io::appendObservationToMap(obs, robotPose.value_or(mrpt::poses::CPose3D()), m_points, report)) return false;
	m_viewpoints.insert(m_viewpoints.end(), report.viewpoints.begin(), report.viewpoints.end());
	m_tagsStale = true;
	return true;
}

}  // namespace tagmap::maps
