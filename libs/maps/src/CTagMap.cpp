// CTagMap: contents, serialization and the small CMetricMap overrides. The
// larger behaviours each have their own file (CTagMap_*.cpp).
#include "tagmap/maps/CTagMap.h"

#include <mrpt/serialization/CArchive.h>

#include <mrpt/core/initializer.h>

#include "tagmap/maps/register_classes.h"
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
// Version 0: options, tags (every TagDetection field), points, stale flag.
// Bump the version and keep reading old ones when the layout changes.
namespace
{
void writeTag(mrpt::serialization::CArchive& out, const TagDetection& t)
{
	out << t.family << static_cast<int32_t>(t.id) << t.size;
	for (const auto& c : t.corners) out << c.x() << c.y() << c.z();
	const Eigen::Matrix4d T = t.pose.matrix();
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 4; c++) out << T(r, c);
	for (int r = 0; r < 6; r++)
		for (int c = 0; c < 6; c++) out << t.covariance(r, c);
	out << static_cast<int32_t>(t.pointsUsed) << t.decodeMargin << t.patternFit << t.mirrored;
}

TagDetection readTag(mrpt::serialization::CArchive& in)
{
	TagDetection t;
	int32_t id = 0, pointsUsed = 0;
	in >> t.family >> id >> t.size;
	t.id = id;
	for (auto& c : t.corners) in >> c.x() >> c.y() >> c.z();
	Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 4; c++) in >> T(r, c);
	t.pose.matrix() = T;
	for (int r = 0; r < 6; r++)
		for (int c = 0; c < 6; c++) in >> t.covariance(r, c);
	in >> pointsUsed >> t.decodeMargin >> t.patternFit >> t.mirrored;
	t.pointsUsed = pointsUsed;
	return t;
}
}  // namespace

uint8_t CTagMap::serializeGetVersion() const { return 0; }

void CTagMap::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << detectionOptions.families << detectionOptions.tagSize << detectionOptions.configFile;
	out << likelihoodOptions.beaconRangesStd << likelihoodOptions.beaconRangesUseObservationStd;
	out << visualOptions.showPoints << visualOptions.showLabels << visualOptions.showAxes << visualOptions.pointSize;
	out << genericMapParams;
	out << static_cast<uint32_t>(m_tags.size());
	for (const auto& t : m_tags) writeTag(out, t);
	out << m_points << m_tagsStale;
}

void CTagMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			in >> detectionOptions.families >> detectionOptions.tagSize >> detectionOptions.configFile;
			in >> likelihoodOptions.beaconRangesStd >> likelihoodOptions.beaconRangesUseObservationStd;
			in >> visualOptions.showPoints >> visualOptions.showLabels >> visualOptions.showAxes >>
				visualOptions.pointSize;
			in >> genericMapParams;
			uint32_t n = 0;
			in >> n;
			m_tags.clear();
			for (uint32_t i = 0; i < n; i++) m_tags.push_back(readTag(in));
			in >> m_points >> m_tagsStale;
		}
		break;
		default: MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}

}  // namespace tagmap::maps
