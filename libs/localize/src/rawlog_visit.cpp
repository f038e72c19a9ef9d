#include "tagmap/localize/rawlog_visit.h"

namespace tagmap::localize
{
void visitRawlog(const mrpt::obs::CRawlog& log, const RawlogVisitor& v)
{
	for (size_t i = 0; i < log.size(); i++)
	{
		const auto type = log.getType(i);
		if (type == mrpt::obs::CRawlog::etActionCollection && v.actions) v.actions(*log.getAsAction(i));
		if (type == mrpt::obs::CRawlog::etSensoryFrame && v.sensoryFrame) v.sensoryFrame(*log.getAsObservations(i));
		if (type == mrpt::obs::CRawlog::etObservation && v.observation) v.observation(log.getAsObservation(i));
	}
}

}  // namespace tagmap::localize
