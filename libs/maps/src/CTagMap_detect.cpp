// Running tagmap::Pipeline on CTagMap's points with the map's own resolved
// settings.
#include "tagmap/maps/CTagMap.h"
#include "tagmap/pipeline.h"

namespace tagmap::maps
{
void CTagMap::detectTags() const
{
	m_tags = Pipeline(detectionParams).detect(m_points, m_viewpoints).tags;
	m_beaconIds.clear();
	m_tagsStale = false;
}

}  // namespace tagmap::maps
