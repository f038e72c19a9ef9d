#include "detect_outputs.h"

#include <mrpt/core/format.h>

#include "tagmap/atomic_file.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/mrpt/landmarks_map.h"
#include "tagmap/mrpt/metric_map_ini.h"
#include "tagmap/mrpt/rawlog_writer.h"
#include "tagmap/mrpt/serialize_gz.h"
#include "tagmap/mrpt/tag_scene.h"
#include "tagmap/pipeline.h"

namespace tagmap::app
{
const std::set<std::string>& mrptOutputOptions()
{
	static const std::set<std::string> options = {"--landmarks", "--tagmap", "--ini", "--rawlog", "--3dscene"};
	return options;
}

void checkMrptOutputs(const cli::Args& args)
{
	for (const auto& opt : mrptOutputOptions())
		if (args.has(opt)) checkOutputWritable(args.get(opt));
}

namespace
{
// The detection settings used travel with the map, so re-running detection
// inside an MRPT app (CTagMap::tags() after new insertions) uses them.
maps::CTagMap::Ptr makeTagMap(const PipelineParams& params, const mrpt::maps::CPointsMapXYZI& map,
							  const std::vector<TagDetection>& tags)
{
	auto m = maps::CTagMap::Create();
	m->detectionParams = params;
	m->setPoints(map);
	m->setTags(tags);  // after setPoints: these tags are current, no re-detection
	return m;
}

// The ini keeps what the user chose (a hand-editable file names a config
// file rather than every parameter); CTagMap resolves it when loaded.
std::vector<std::pair<std::string, std::string>> iniDetectionKeys(const DetectionChoices& c)
{
	return {{"families", c.families}, {"tagSize", mrpt::format("%.9g", c.tagSize)}, {"configFile", c.configFile}};
}
}  // namespace

void writeMrptOutputs(const cli::Args& args, const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
					  const std::vector<TagDetection>& tags)
{
	if (args.has("--landmarks")) mrpt_bridge::writeLandmarksMap(args.get("--landmarks"), tags);
	if (args.has("--3dscene")) mrpt_bridge::write3DScene(args.get("--3dscene"), map, tags);
	if (args.has("--ini"))
	{
		mrpt_bridge::MetricMapIniParams p;
		p.tagMapDetectionOptions = iniDetectionKeys(used.choices);
		mrpt_bridge::writeMetricMapIni(args.get("--ini"), tags, p);
	}
	if (args.has("--rawlog")) mrpt_bridge::writeTagRawlog(args.get("--rawlog"), map, tags);
	// A .tagmap is one serialized CTagMap, which is also a valid one-entry
	// rawlog: `RawLogViewer -l plugin F.tagmap` shows it (docs/MRPT.md).
	if (args.has("--tagmap")) mrpt_bridge::writeSerializableGz(args.get("--tagmap"), *makeTagMap(used.params, map, tags));
}

void writeMrptOutputs(const cli::Args& args, const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
					  const tagmap::Detections& found)
{
	writeMrptOutputs(args, used, map, found.tags);
}

}  // namespace tagmap::app
