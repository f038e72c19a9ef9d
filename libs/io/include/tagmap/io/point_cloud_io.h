// Reading the maps users have into mrpt::maps::CPointsMapXYZI, and writing
// binary PCD. The format is chosen from the file extension:
//   .pcd (ascii, binary, binary_compressed), .ply (ascii, binary LE),
//   .bin (KITTI x y z i float32), .xyzi / .txt / .xyz (plain text "x y z i"),
//   .simplemap (MRPT keyframes merged at their poses), .las (LAS 1.0-1.4).
// Coordinates are read in double whatever the file stores (PCD/PLY float64,
// LAS scaled integers) and stored as float relative to a local origin (see
// LoadReport::origin): a UTM map keeps millimetres in float32.
// Every malformed input throws tagmap::InputError with a one-line message
// "<file>: <place>: <what>", never crashes and never allocates what a header
// merely claims.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tagmap::io
{
/** Points with a coordinate farther than this from the local origin
 *  (metres) are skipped and counted like NaN ones: 10000 km is more than any
 *  place on Earth is from another, so such values are corrupt or sentinel
 *  data (1e30, FLT_MAX). Stray returns a few thousand km off are kept: the
 *  pipeline's neighbour index has no extent limit. */
constexpr double kMaxAbsCoordinate = 1e7;

/** Maps farther than this from the file's origin (metres, per axis) get a
 *  local origin; nearer ones are stored as they are (origin 0), so ordinary
 *  maps load exactly as before. At 1 km a float32 step is 0.06 mm. */
constexpr double kLocalOriginBeyond = 1000;

struct LoadParams
{
	/** The local origin to subtract (the file's frame), instead of the one
	 *  chosen from the points. */
	bool fixedOrigin = false;
	Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

struct LoadReport
{
	std::string format;  // "pcd-binary", "ply-ascii", "kitti", "simplemap", ...
	std::string intensityField;  // name of the field the intensity came from
	size_t pointsRead = 0;  // points in the file
	size_t pointsKept = 0;  // finite points put into the map
	size_t nonFiniteSkipped = 0;  // NaN/Inf coordinates or intensity
	size_t outOfRangeSkipped = 0;  // a coordinate beyond kMaxAbsCoordinate from the origin
	/** The map holds file coordinates minus this (the local frame); add it
	 *  back to anything found in the map. Whole metres, so it prints exactly. */
	Eigen::Vector3d origin = Eigen::Vector3d::Zero();
	bool originFixed = false;  // set by the readers once origin is decided
	// .simplemap (and later rawlogs): observations merged into the map, and
	// observations passed over because they carry no usable intensity.
	size_t observationsUsed = 0;
	size_t observationsSkipped = 0;
	/** Where the sensor stood for each observation used (robot pose (+)
	 *  sensor pose), in the file's frame like `origin`: subtract it for the
	 *  map's local frame (localViewpoints()). Empty for point-cloud files. */
	std::vector<Eigen::Vector3d> viewpoints;
	std::vector<Eigen::Vector3d> localViewpoints() const;
	/** Set by the caller to hear how far a long read is: called with the
	 *  points read so far, every kProgressPoints points, on the calling thread. */
	std::function<void(size_t pointsSoFar)> progress;
	static constexpr size_t kProgressPoints = size_t{1} << 20;
};

/** The extensions loadPointCloud() understands, for messages and --help. */
const char* supportedExtensions();

/** The local origin for points (file frame): per axis, the median rounded
 *  to whole metres, or 0 when within kLocalOriginBeyond of the file's
 *  origin. The median, not the centre of the bounds, so stray returns
 *  thousands of km away do not move it. Points not finite or farther than
 *  kMaxAbsCoordinate from the file's origin (sentinels) are left out. */
Eigen::Vector3d chooseLocalOrigin(std::vector<Eigen::Vector3d> points);

/** Loads any supported file into `out` (cleared first). Throws InputError.
 *  The origin is chosen from the first points read; if the whole map's
 *  median turns out farther than kLocalOriginBeyond from it (a file that
 *  starts with outliers or at one end of a long survey), it is read again
 *  around the whole map's median. */
void loadPointCloud(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport* report = nullptr,
					const LoadParams& params = {});

/** Convenience form of the above. */
mrpt::maps::CPointsMapXYZI loadPointCloud(const std::string& path, LoadReport* report = nullptr,
										  const LoadParams& params = {});

/** Writes a binary PCD v0.7 (FIELDS x y z intensity) atomically: x y z as
 *  F4, or, with a non-zero `shift` added to every point, as F8 (a
 *  georeferenced map: float32 would round UTM coordinates to 0.5 m). */
void savePcdBinary(const std::string& path, const mrpt::maps::CPointsMapXYZI& map,
				   const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());

struct LasWriteParams
{
	int pointFormat = 6;  // 0..10; LAS 1.2 for 0-3, 1.4 otherwise
	double scale = 0.001;  // metres per count, all axes
	Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // added to every point
};

/** Writes a LAS file atomically (intensity stretched to 0..65535). Throws
 *  std::invalid_argument for a bad format or a map the int32 counts cannot hold. */
void saveLas(const std::string& path, const mrpt::maps::CPointsMapXYZI& map, const LasWriteParams& params = {});

}  // namespace tagmap::io
