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
	if (ext == ".las") return detail::readLas;
	if (ext == ".laz")
		throw InputError(path, "", "LAZ (compressed LAS) is not read; decompress it first, e.g. 'laszip -i " +
									   std::filesystem::path(path).filename().string() + " -o map.las' or 'pdal translate'");
	throw InputError(path, "",
					 (ext.empty() ? std::string("no file extension") : "unknown file extension '" + ext + "'") + "; supported: " + supportedExtensions());
}

}  // namespace

const char* supportedExtensions() { return ".pcd .ply .bin (KITTI) .xyzi .txt .xyz .simplemap .rawlog .las"; }

namespace
{
/** chooseLocalOrigin() for the whole stored map (local frame around
 *  `origin`), from an evenly strided sample, in the file's frame. */
Eigen::Vector3d wholeMapOrigin(const mrpt::maps::CPointsMapXYZI& map, const Eigen::Vector3d& origin)
{
	const size_t n = map.size(), step = std::max<size_t>(1, n / 100000);
	std::vector<Eigen::Vector3d> sample;
	sample.reserve(n / step + 1);
	for (size_t i = 0; i < n; i += step)
		sample.push_back(origin + Eigen::Vector3d(map.getPointsBufferRef_x()[i], map.getPointsBufferRef_y()[i],
												  map.getPointsBufferRef_z()[i]));
	return chooseLocalOrigin(std::move(sample));
}
}  // namespace

void loadPointCloud(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport* report, const LoadParams& params)
{
	const Reader read = readerFor(path);
	LoadReport local;  // the caller's report is filled only on success
	try
	{
		for (int attempt = 0;; ++attempt)
		{
			// resize(0), not clear(): clear() frees the buffers, and a caller that
			// reloads into the same map would pay to allocate and fault them again.
			out.resize(0);
			out.mark_as_modified();
			const Eigen::Vector3d origin = attempt == 0 ? params.origin : local.origin;
			local = LoadReport();
			// Progress is heard once: a second reading counts silently.
			if (report && attempt == 0) local.progress = report->progress;
			local.origin = origin;
			local.originFixed = params.fixedOrigin || attempt > 0;
			read(path, out, local);
			if (params.fixedOrigin || attempt > 0) break;
			// The first points chose the origin; once the whole map is known,
			// a median far from it (the file began with outliers, or at one
			// end of a long survey) costs precision: read again around it.
			const Eigen::Vector3d whole = wholeMapOrigin(out, local.origin);
			if ((whole - local.origin).cwiseAbs().maxCoeff() <= kLocalOriginBeyond) break;
			local.origin = whole;
		}
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

mrpt::maps::CPointsMapXYZI loadPointCloud(const std::string& path, LoadReport* report, const LoadParams& params)
{
	mrpt::maps::CPointsMapXYZI map;
	loadPointCloud(path, map, report, params);
	return map;
}

}  // namespace tagmap::io
