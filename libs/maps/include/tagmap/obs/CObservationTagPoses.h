// tagmap::obs::CObservationTagPoses: the tags one LiDAR scan saw, each with
// its full 6-DoF pose relative to the sensor (T_sensor_tag) and the 6x6
// covariance from the detector. Written by `tagmap observe` next to the
// scan and a CObservationBeaconRanges: the beacon ranges are what MRPT's
// stock range-only localizers understand; this keeps everything the
// detector knows (orientation included) for localizers that can use it.
//
// Registered with MRPT's class registry by any program that links it
// (register_classes.h), so tagmap programs read it back from rawlogs, and by
// the plugin, so `RawLogViewer -l libtagmap_mrpt_plugin.so` shows its
// description (getDescriptionAsText).
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/opengl/Visualizable.h>
#include <mrpt/poses/CPose3D.h>

#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::obs
{
class CObservationTagPoses : public mrpt::obs::CObservation, public mrpt::opengl::Visualizable
{
	DEFINE_SERIALIZABLE(CObservationTagPoses, tagmap::obs)

   public:
	/** The LiDAR's pose on the robot (the scan's own sensorPose). */
	mrpt::poses::CPose3D sensorPose;

	/** Tags in the sensor frame: `pose` is T_sensor_tag, `covariance` is
	 *  [x y z | rx ry rz] in the sensor frame (docs/RESULT_FORMAT.md, TagDetection),
	 *  corners in the sensor frame. Sorted by family, then id. */
	std::vector<TagDetection> tags;

	/** The tag with this family and id, or nullptr. */
	const TagDetection* find(const std::string& family, int id) const;

	// CObservation
	void getSensorPose(mrpt::poses::CPose3D& out) const override { out = sensorPose; }
	void setSensorPose(const mrpt::poses::CPose3D& p) override { sensorPose = p; }
	/** Base info, then one line per tag: beacon ID, family:id, size, range,
	 *  position, roll/pitch/yaw and standard deviations (cm, degrees). */
	void getDescriptionAsText(std::ostream& o) const override;

	// Visualizable: each tag (bitmap, label, axes) where the sensor sees it,
	// in the robot frame (sensorPose applied).
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
};

}  // namespace tagmap::obs
