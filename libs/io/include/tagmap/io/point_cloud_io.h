// Reading the maps users have into mrpt::maps::CPointsMapXYZI, and writing
// binary PCD. The format is chosen from the file extension:
//   .pcd (ascii, binary, binary_compressed), .ply (ascii, binary LE),
//   .bin (KITTI x y z i float32), .xyzi / .txt / .xyz (plain text "x y z i"),
//   .simplemap (MRPT keyframes merged at their poses).
// Every malformed input throws tagmap::InputError with a one-line message
// "<file>: <place>: <what>", never crashes and never allocates what a header
// merely claims.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <cstddef>
#include <functional>
#include <string>

namespace tagmap::io
{
/** Points with a coordinate farther than this from the origin (metres) are
 *  skipped and counted like NaN ones: no LiDAR map spans 1000 km, such values
 *  are corrupt or sentinel data, and they would blow up the pipeline's voxel
 *  grid, which covers the map's bounding box. */
constexpr float kMaxAbsCoordinate = 1e6f;

struct LoadReport
{
	std::string format;  // "pcd-binary", "ply-ascii", "kitti", "simplemap", ...
	std::string intensityField;  // name of the field the intensity came from
	size_t pointsRead = 0;  // points in the file
	size_t pointsKept = 0;  // finite points put into the map
	size_t nonFiniteSkipped = 0;  // NaN/Inf coordinates or intensity
	size_t outOfRangeSkipped = 0;  // a coordinate beyond kMaxAbsCoordinate
	// .simplemap (and later rawlogs): observations merged into the map, and
	// observations passed over because they carry no usable intensity.
	size_t observationsUsed = 0;
	size_t observationsSkipped = 0;
	/** Set by the caller to hear how far a long read is: called with the
	 *  points read so far, every kProgressPoints points, on the calling thread. */
	std::function<void(size_t pointsSoFar)> progress;
	static constexpr size_t kProgressPoints = size_t{1} << 20;
};

/** The extensions loadPointCloud() understands, for messages and --help. */
const char* supportedExtensions();

/** Loads any supported file into `out` (cleared first). Throws InputError. */
void loadPointCloud(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport* report = nullptr);

/** Convenience form of the above. */
mrpt::maps::CPointsMapXYZI loadPointCloud(const std::string& path, LoadReport* report = nullptr);

/** Writes a binary PCD v0.7 (FIELDS x y z intensity, F4) atomically. */
void savePcdBinary(const std::string& path, const mrpt::maps::CPointsMapXYZI& map);

}  // namespace tagmap::io
