// MRPT .simplemap: keyframes (pose PDF + sensory frame), gzip-compressed or
// not; every observation with intensity is merged at its keyframe's mean pose.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/serialization/CArchive.h>

#include <map>
#include <new>

#include "reader_common.h"
#include "readers.h"
#include "tagmap/io/mrpt_observations.h"

namespace tagmap::io::detail
{
namespace
{
mrpt::maps::CSimpleMap readSimpleMap(const std::string& path)
{
	{
		const FileBytes probe(path);  // existence and "regular file" checks, with errno text
		if (probe.size() == 0) throw InputError(path, "", "file is empty");
	}
	mrpt::io::CFileGZInputStream in;
	if (!in.open(path)) throw InputError(path, "", "cannot open");
	mrpt::maps::CSimpleMap sm;
	try
	{
		auto archive = mrpt::serialization::archiveFrom(in);
		archive >> sm;
	}
	catch (const std::bad_alloc&)
	{
		throw InputError(path, "", "not a readable MRPT simplemap (corrupt size field)");
	}
	catch (const std::exception& e)
	{
		throw InputError(path, "", "not a readable MRPT simplemap: " + errorSummary(e.what()));
	}
	return sm;
}

}  // namespace

void readSimplemap(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const mrpt::maps::CSimpleMap sm = readSimpleMap(path);
	report.format = "simplemap";
	report.intensityField = "observation intensity";
	std::map<std::string, size_t> skippedKinds;
	size_t keyframe = 0;
	for (const auto& pair : sm)
	{
		++keyframe;
		if (!pair.pose || !pair.sf) continue;
		const mrpt::poses::CPose3D pose = pair.pose->getMeanVal();
		for (const auto& obs : *pair.sf)
		{
			if (!obs) continue;
			try
			{
				if (!appendObservationToMap(*obs, pose, out, report)) ++skippedKinds[obs->GetRuntimeClass()->className];
			}
			catch (const InputError&)
			{
				throw;
			}
			catch (const std::exception& e)
			{
				throw InputError(path, "keyframe " + std::to_string(keyframe), std::string(obs->GetRuntimeClass()->className) + ": " + errorSummary(e.what()));
			}
		}
	}
	if (report.observationsUsed == 0)
	{
		std::string kinds;
		for (const auto& [name, n] : skippedKinds) kinds += (kinds.empty() ? "" : ", ") + name + " x" + std::to_string(n);
		throw InputError(path, "",
						 "no observation with intensity in " + std::to_string(sm.size()) + " keyframes (found: " + (kinds.empty() ? "none" : kinds) +
							 "); expected CObservationPointCloud with a CPointsMapXYZI, CObservationVelodyneScan or CObservation3DRangeScan with intensity");
	}
}

}  // namespace tagmap::io::detail
