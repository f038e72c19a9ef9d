// CObservationTagPoses for people: the text RawLogViewer shows when the
// observation is selected, and a 3D view with the same tag visuals as the
// rest of tagmap's MRPT outputs (tagmap/mrpt/tag_visual.h).
#include <mrpt/opengl/CSetOfObjects.h>

#include <ostream>

#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/mrpt/tag_visual.h"
#include "tagmap/obs/CObservationTagPoses.h"
#include "tagmap/tag_table.h"

namespace tagmap::obs
{
void CObservationTagPoses::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Sensor pose on the robot: " << sensorPose << "\n";
	o << tags.size() << " tag(s), poses T_sensor_tag in the sensor frame:\n";
	TagTableColumns columns;
	columns.firstHeader = "beacon";
	columns.first = [](const TagDetection& t) {
		try
		{
			return std::to_string(mrpt_bridge::encodeBeaconId(t.family, t.id));
		}
		catch (const std::exception&)
		{
			return std::string("-");  // a family without a beacon index still gets its line
		}
	};
	columns.range = true;
	columns.stdDev = true;
	o << tagTable(tags, columns);
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
