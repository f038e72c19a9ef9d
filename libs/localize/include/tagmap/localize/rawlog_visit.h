// Walking a rawlog of either format (action/sensory-frame pairs or bare
// observations) entry by entry, so every reader handles both the same way.
#pragma once

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <functional>

namespace tagmap::localize
{
struct RawlogVisitor
{
	std::function<void(const mrpt::obs::CActionCollection&)> actions;
	std::function<void(const mrpt::obs::CSensoryFrame&)> sensoryFrame;
	std::function<void(const mrpt::obs::CObservation::Ptr&)> observation;  // a bare one, not in a frame
};

/** Calls the visitor's functions (those that are set) in log order; other
 *  entries are skipped. */
void visitRawlog(const mrpt::obs::CRawlog& log, const RawlogVisitor& v);

}  // namespace tagmap::localize
