#include "tagmap/mrpt/rawlog_writer.h"

#include <mrpt/obs/CObservation3DScene.h>
#include <mrpt/system/datetime.h>

#include "tagmap/mrpt/serialize_gz.h"

namespace tagmap::mrpt_bridge
{
void writeTagRawlog(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
					const std::vector<TagDetection>& tags, const RawlogParams& params)
{
	auto obs = mrpt::obs::CObservation3DScene::Create();
	obs->sensorLabel = params.sensorLabel;
	obs->timestamp = mrpt::Clock::now();
	obs->scene = buildTagScene(map, tags, params.scene);

	writeSerializableSequenceGz(path, {obs});
}

}  // namespace tagmap::mrpt_bridge
