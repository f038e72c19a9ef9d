// CObservationTagPoses for people: the text RawLogViewer shows when the
// observation is selected, and a 3D view with the same tag visuals as the
// rest of tagmap's MRPT outputs (tagmap/mrpt/tag_visual.h).
#include <mrpt/opengl/CSetOfObjects.h>

#include <cmath>
#include <cstdio>
#include <ostream>

#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/tag_visual.h"
#include "tagmap/obs/CObservationTagPoses.h"

namespace tagmap::obs
{
void CObservationTagPoses::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Sensor pose on the robot: " << sensorPose << "\n";
	o << tags.size() << " tag(s), poses T_sensor_tag in the sensor frame:\n";
	o << "  beacon    tag               size   range |        x        y        z |  roll pitch   yaw [deg]"
		 " | std xyz [cm] | std rpy [deg]\n";
	char line[320];
	for (const TagDetection& t : tags)
	{
		const Eigen::Vector3d p = t.position();
		const Eigen::Vector3d rpy = rollPitchYaw(t.pose.linear()) * (180.0 / M_PI);
		const auto sd = [&](int i) { return std::sqrt(std::max(0.0, t.covariance(i, i))); };
		long long beacon = -1;
		try
		{
			beacon = mrpt_bridge::encodeBeaconId(t.family, t.id);
		}
		catch (const std::exception&)
		{
			// A family without a beacon index still gets its line.
		}
		std::snprintf(line, sizeof line,
					  "  %-9lld %-16s %5.3f %7.3f | %8.3f %8.3f %8.3f | %5.1f %5.1f %5.1f | %4.1f %4.1f %4.1f | "
					  "%4.2f %4.2f %4.2f\n",
					  beacon, (t.family + ":" + std::to_string(t.id)).c_str(), t.size, p.norm(), p.x(), p.y(), p.z(),
					  rpy.x(), rpy.y(), rpy.z(), 100 * sd(0), 100 * sd(1), 100 * sd(2), sd(3) * 180 / M_PI,
					  sd(4) * 180 / M_PI, sd(5) * 180 / M_PI);
		o << line;
	}
}

void CObservationTagPoses::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const
{
	auto inSensor = mrpt::opengl::CSetOfObjects::Create();
	inSensor->setPose(sensorPose);
	for (const TagDetection& t : tags)
	{
		try
		{
			inSensor->insert(mrpt_bridge::makeTagVisual(t));
		}
		catch (const std::invalid_argument&)
		{
			// Unknown family/id: nothing to draw, the text view still lists it.
		}
	}
	o.insert(inSensor);
}

}  // namespace tagmap::obs
