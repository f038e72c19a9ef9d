// CTagMap: contents, serialization and the small CMetricMap overrides. The
// larger behaviours each have their own file (CTagMap_*.cpp).
#include "tagmap/maps/CTagMap.h"

#include <mrpt/core/initializer.h>
#include <mrpt/serialization/CArchive.h>

#include <iostream>
#include <sstream>

#include "tagmap/detection_settings.h"
#include "tagmap/errors.h"
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
	m_beaconIds.clear();
	m_tagsStale = false;
}

void CTagMap::setPoints(const mrpt::maps::CPointsMapXYZI& points, const std::vector<Eigen::Vector3d>& viewpoints)
{
	m_points = points;
	m_viewpoints = viewpoints;
	m_tagsStale = !m_points.empty();
}

bool CTagMap::isEmpty() const { return m_tags.empty() && m_points.empty(); }

void CTagMap::internal_clear()
{
	m_points.clear();
	m_viewpoints.clear();
	m_tags.clear();
	m_beaconIds.clear();
	m_tagsStale = false;
}

void CTagMap::saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const
{
	writeTagsJson(filNamePrefix + "_tags.json", tags());
}

// ---- serialization ---------------------------------------------------------
// Version 4: as 3, with the likelihood option scoreBeaconRanges.
// Version 3: as 2, with every likelihood option (tag poses too).
// Version 2: the resolved detection settings (PipelineParams as the YAML of
// `tagmap config --dump`, which names every key, so a later version with more
// keys still reads it), likelihood and visual options, generic map params,
// tags (tag_detection_archive.h, with its own version byte), points, stale flag.
// Version 1: as 2, but the detection choices (families, tag size, config
// file path) instead of the settings.
// Version 0 (tagmap 0.1): as 1, with the tags as a bare count and layout-0
// tags (the layout tag_detection_archive.h took over).
uint8_t CTagMap::serializeGetVersion() const { return 5; }

namespace
{
std::string paramsText(const PipelineParams& p)
{
	std::ostringstream s;
	p.toYaml().printAsYAML(s);
	return s.str();
}

/** Versions 0 and 1 stored the choices; the settings they give are resolved
 *  here. A config file that is not on this machine (the map came from
 *  elsewhere) falls back to the built-in defaults with the other choices:
 *  the stored tags are unaffected, only a re-detection would differ. */
PipelineParams resolveStoredChoices(const DetectionChoices& c)
{
	try
	{
		return resolveDetectionSettings(c);
	}
	catch (const InputError& e)
	{
		std::cerr << "CTagMap: " << e.what() << "; re-detection uses the built-in defaults\n";
		DetectionChoices withoutFile = c;
		withoutFile.configFile.clear();
		return resolveDetectionSettings(withoutFile);
	}
}
}  // namespace

void CTagMap::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << paramsText(detectionParams);
	writeLikelihoodOptions(out, likelihoodOptions);
	out << visualOptions.showPoints << visualOptions.showLabels << visualOptions.showAxes << visualOptions.pointSize;
	out << genericMapParams;
	writeTagDetections(out, m_tags);
	out << m_points << m_tagsStale;
	out << static_cast<uint32_t>(m_viewpoints.size());
	for (const Eigen::Vector3d& v : m_viewpoints) out << v.x() << v.y() << v.z();
}

void CTagMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version > 5) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	if (version >= 2)
	{
		std::string yaml;
		in >> yaml;
		detectionParams = PipelineParams::fromYaml(mrpt::containers::yaml::FromText(yaml));
	}
	else
	{
		DetectionChoices c;
		in >> c.families >> c.tagSize >> c.configFile;
		detectionParams = resolveStoredChoices(c);
	}
	likelihoodOptions = TTagLikelihoodOptions();
	if (version >= 3)
		readLikelihoodOptions(in, likelihoodOptions,
							  version == 3 ? LikelihoodOptionsLayout::v3 : LikelihoodOptionsLayout::current);
	else
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
	m_beaconIds.clear();
	in >> m_points >> m_tagsStale;
	m_viewpoints.clear();
	if (version >= 5)
	{
		uint32_t n = 0;
		in >> n;
		for (uint32_t k = 0; k < n; k++)
		{
			double x = 0, y = 0, z = 0;
			in >> x >> y >> z;
			m_viewpoints.emplace_back(x, y, z);
		}
	}
}

}  // namespace tagmap::maps
