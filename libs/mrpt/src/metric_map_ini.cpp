#include "tagmap/mrpt/metric_map_ini.h"

#include <mrpt/core/format.h>

#include <sstream>

#include "tagmap/atomic_file.h"
#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/tags_ini.h"

namespace tagmap::mrpt_bridge
{
std::string metricMapIni(const std::vector<TagDetection>& tags, const MetricMapIniParams& params)
{
	const std::string& S = params.sectionName;
	std::ostringstream o;
	o << "; Written by tagmap: " << tags.size() << " fiducial tags as range-only beacons"
	  << (params.includeTagMap ? " (landmarksMap) and as tags (tagMap, with the tagmap plugin).\n" : ".\n")
	  << "; Beacon ID = familyIndex * " << kBeaconIdStride << " + tag id (docs/MRPT.md),\n"
	  << "; e.g. " << encodeBeaconId("tag36h11", 3) << " = tag36h11 #3.\n"
	  << "[" << S << "]\n"
	  << "landmarksMap_count=1\n";
	if (params.includeTagMap)
		o << "; Read only when the tagmap MRPT plugin is loaded; stock MRPT ignores it.\n"
		  << "tagMap_count=1\n";

	o << "\n[" << S << "_landmarksMap_00_creationOpts]\n"
	  << "nBeacons=" << tags.size() << "\n";
	for (unsigned i = 1; i <= tags.size(); i++)
	{
		const auto& t = tags[i - 1];
		const Eigen::Vector3d c = t.position();
		o << mrpt::format("; %s #%d, size %.4g m\n", t.family.c_str(), t.id, t.size)
		  << mrpt::format("beacon_%03u_ID=%lld\n", i, static_cast<long long>(encodeBeaconId(t.family, t.id)))
		  << mrpt::format("beacon_%03u_x=%.9g\nbeacon_%03u_y=%.9g\nbeacon_%03u_z=%.9g\n", i, c.x(), i, c.y(), i, c.z());
	}
	o << "\n[" << S << "_landmarksMap_00_likelihoodOpts]\n"
	  << mrpt::format("beaconRangesStd=%g\n", params.beaconRangesStd);

	if (params.includeTagMap)
	{
		// The tagMap scores the tag poses; the landmarksMap already scores
		// the beacon ranges, so the tagMap leaves them (scoreBeaconRanges):
		// both would count every range twice.
		o << "\n[" << S << "_tagMap_00_creationOpts]\n"
		  << "enableObservationLikelihood=true\n";
		writeTagsIniKeys(o, tags);
		o << "\n[" << S << "_tagMap_00_detectionOpts]\n";
		for (const auto& [k, v] : params.tagMapDetectionOptions) o << k << "=" << v << "\n";
		o << "\n[" << S << "_tagMap_00_likelihoodOpts]\n"
		  << "scoreBeaconRanges=false  ; the landmarksMap scores them\n"
		  << "; Added to each seen tag's std: one update per scan from a uniform start\n"
		  << "; needs a model as wide as the particles are apart (docs/MRPT.md).\n"
		  << mrpt::format("tagPoseExtraStdPosition=%g\n", params.tagPoseExtraStdPosition)
		  << mrpt::format("tagPoseExtraStdRotationDeg=%g\n", params.tagPoseExtraStdRotationDeg);
	}
	return o.str();
}

void writeMetricMapIni(const std::string& path, const std::vector<TagDetection>& tags, const MetricMapIniParams& params)
{
	const std::string text = metricMapIni(tags, params);
	writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace tagmap::mrpt_bridge
