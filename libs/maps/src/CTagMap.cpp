// CTagMap: contents, serialization and the small CMetricMap overrides. The
// larger behaviours each have their own file (CTagMap_*.cpp).
#include "tagmap/maps/CTagMap.h"

#include <mrpt/serialization/CArchive.h>

#include <mrpt/core/initializer.h>

#include "tagmap/maps/register_classes.h"
#include "tagmap/maps/tag_detection_archive.h"
#include "tagmap/tags_json.h"

IMPLEMENTS_SERIALIZABLE(CTagMap, mrpt::maps::CMetricMap, tagmap::maps)

// A program that links CTagMap can read it (and CObservationTagPoses) back by
// name and load "tagMap" from ini files, without calling anything first.
MRPT_INITIALIZER(tagmap_register_classes_with_CTagMap) { tagmap::maps::registerClasses(); }

namespace tagmap::maps
{
const std::vector<TagDetection>& CTagMap::tags() const
{
	if (m_tagsStale) detectTags();
	return m_tags;
}

void CTagMap::setTags(std::vector<TagDetection> tags)
{
	m_tags = std::move(tags);
	m_tagsStale = false;
}

void CTagMap::setPoints(const mrpt::maps::CPointsMapXYZI& points)
{
	m_points = points;
	m_tagsStale = !m_points.empty();
}

bool CTagMap::isEmpty() const { return m_tags.empty() && m_points.empty(); }

void CTagMap::internal_clear()
{
	m_points.clear();
	m_tags.clear();
	m_tagsStale = false;
}

void CTagMap::saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const
{
	writeTagsJson(filNamePrefix + "_tags.json", tags());
}

// ---- serialization ---------------------------------------------------------
// Version 1: options, generic map params, tags (tag_detection_archive.h, with
// its own version byte), points, stale flag.
// Version 0 (tagmap 0.1): the same with the tags as a bare count and layout-0
// tags (the layout tag_detection_archive.h took over).
uint8_t CTagMap::serializeGetVersion() const { return 1; }

void CTagMap::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << detectionOptions.families << detectionOptions.tagSize << detectionOptions.configFile;
	out << likelihoodOptions.beaconRangesStd << likelihoodOptions.beaconRangesUseObservationStd;
	out << visualOptions.showPoints << visualOptions.showLabels << visualOptions.showAxes << visualOptions.pointSize;
	out << genericMapParams;
	writeTagDetections(out, m_tags);
	out << m_points << m_tagsStale;
}

void CTagMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	in >> detectionOptions.families >> detectionOptions.tagSize >> detectionOptions.configFile;
	in >> likelihoodOptions.beaconRangesStd >> likelihoodOptions.beaconRangesUseObservationStd;
	in >> visualOptions.showPoints >> visualOptions.showLabels >> visualOptions.showAxes >> visualOptions.pointSize;
	in >> genericMapParams;
	if (version == 0)
	{
		uint32_t n = 0;
		in >> n;
		m_tags.clear();
		for (uint32_t i = 0; i < n; i++) m_tags.push_back(readTagDetection(in, 0));
	}
	else
		m_tags = readTagDetections(in);
	in >> m_points >> m_tagsStale;
}

}  // namespace tagmap::maps
