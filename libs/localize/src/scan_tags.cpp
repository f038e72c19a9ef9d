#include "tagmap/localize/scan_tags.h"

#include "tagmap/io/mrpt_observations.h"

namespace tagmap::localize
{
PipelineParams singleScanPipelineParams(size_t window)
{
	PipelineParams p;
	p.sensorView.enabled = window <= 1;
	return p;
}

std::optional<mrpt::maps::CPointsMapXYZI> scanInSensorFrame(const mrpt::obs::CObservation& obs)
{
	// appendObservationToMap places points at robotPose (+) sensorPose;
	// robotPose = sensorPose^-1 leaves them in the sensor frame.
	mrpt::poses::CPose3D sensorPose;
	obs.getSensorPose(sensorPose);
	mrpt::maps::CPointsMapXYZI scan;
	io::LoadReport report;
	if (!io::appendObservationToMap(obs, -sensorPose, scan, report)) return std::nullopt;
	return scan;
}

std::vector<TagDetection> detectTagsInScan(const Pipeline& pipeline, const mrpt::maps::CPointsMapXYZI& scan)
{
	return pipeline.detect(scan).tags;
}

}  // namespace tagmap::localize
