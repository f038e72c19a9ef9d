// Entry point: picks the reader from the file extension and keeps the
// "cleared first, whole or nothing" promise of point_cloud_io.h.
#include <algorithm>
#include <filesystem>
#include <new>

#include "readers.h"
#include "tagmap/errors.h"

namespace tagmap::io
{
namespace
{
using Reader = void (*)(const std::string&, mrpt::maps::CPointsMapXYZI&, LoadReport&);

std::string lowerExtension(const std::string& path)
{
	std::string name = std::filesystem::path(path).filename().string();
	std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
	if (name.size() > 13 && name.compare(name.size() - 13, 13, ".simplemap.gz") == 0) return ".simplemap";
	const size_t dot = name.rfind('.');
	return dot == std::string::npos ? std::string() : name.substr(dot);
}

Reader readerFor(const std::string& path)
{
	const std::string ext = lowerExtension(path);
	if (ext == ".pcd") return detail::readPcd;
	if (ext == ".ply") return detail::readPly;
	if (ext == ".bin") return detail::readKitti;
	if (ext == ".xyzi" || ext == ".txt" || ext == ".xyz") return detail::readXyziText;
	if (ext == ".simplemap") return detail::readSimplemap;
	if (ext == ".rawlog") return detail::readRawlog;
	throw InputError(path, "",
					 (ext.empty() ? std::string("no file extension") : "unknown file extension '" + ext + "'") + "; supported: " + supportedExtensions());
}

}  // namespace

const char* supportedExtensions() { return ".pcd .ply .bin (KITTI) .xyzi .txt .xyz .simplemap .rawlog"; }

void loadPointCloud(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport* report)
{
	// resize(0), not clear(): clear() frees the buffers, and a caller that
	// reloads into the same map would pay to allocate and fault them again.
	out.resize(0);
	out.mark_as_modified();
	const Reader read = readerFor(path);
	LoadReport local;  // the caller's report is filled only on success
	if (report) local.progress = report->progress;
	try
	{
		read(path, out, local);
	}
	catch (const std::bad_alloc&)
	{
		out.clear();
		throw InputError(path, "", "out of memory while loading");
	}
	catch (...)
	{
		out.clear();
		throw;
	}
	if (report) *report = local;
}

mrpt::maps::CPointsMapXYZI loadPointCloud(const std::string& path, LoadReport* report)
{
	mrpt::maps::CPointsMapXYZI map;
	loadPointCloud(path, map, report);
	return map;
}

}  // namespace tagmap::io
