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
maps::CTagMap::Ptr makeTagMap(const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
							  const std::vector<TagDetection>& tags)
{
	auto m = maps::CTagMap::Create();
	m->detectionParams = used.params;
	m->setPoints(map, used.viewpoints);
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
					  const std::vector<TagDetection>& tags, const Eigen::Vector3d& origin)
{
	// Everything MRPT reads stays in the local frame. The scene and rawlog
	// views hold float points (the origin goes in the cloud's name), and
	// CLandmarksMap, which the ini also builds in pf-localization, keeps a
	// 0.2 m grid of its landmarks grown from 0: UTM coordinates ended in
	// std::bad_alloc.
	if (args.has("--landmarks")) mrpt_bridge::writeLandmarksMap(args.get("--landmarks"), tags);
	mrpt_bridge::TagSceneParams sceneParams;
	sceneParams.cloud.localOrigin = origin;
	if (args.has("--3dscene")) mrpt_bridge::write3DScene(args.get("--3dscene"), map, tags, sceneParams);
	if (args.has("--ini"))
	{
		mrpt_bridge::MetricMapIniParams p;
		p.tagMapDetectionOptions = iniDetectionKeys(used.choices);
		mrpt_bridge::writeMetricMapIni(args.get("--ini"), tags, p);
	}
	if (args.has("--rawlog"))
	{
		mrpt_bridge::RawlogParams rp;
		rp.scene = sceneParams;
		mrpt_bridge::writeTagRawlog(args.get("--rawlog"), map, tags, rp);
	}
	// A .tagmap is one serialized CTagMap, which is also a valid one-entry
	// rawlog: `RawLogViewer -l plugin F.tagmap` shows it (docs/MRPT.md).
	if (args.has("--tagmap")) mrpt_bridge::writeSerializableGz(args.get("--tagmap"), *makeTagMap(used, map, tags));
}

void writeMrptOutputs(const cli::Args& args, const DetectionUsed& used, const mrpt::maps::CPointsMapXYZI& map,
					  const tagmap::Detections& found, const Eigen::Vector3d& origin)
{
	writeMrptOutputs(args, used, map, found.tags, origin);
}

}  // namespace tagmap::app
