// Pieces every reader shares: the file's bytes, the typed-column copy into
// the map, text line/number parsing and the intensity field names. Private to
// tagmap_io.
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "tagmap_io reads little-endian PCD/PLY/KITTI data by memcpy; port it before building big-endian"
#endif

namespace tagmap::io::detail
{
/** A whole file, mapped read-only: no copy, and the kernel pages it in as the
 *  reader walks through it, so memory stays at "file + map". */
class FileBytes
{
   public:
	explicit FileBytes(const std::string& path);  // throws InputError
	~FileBytes();
	FileBytes(const FileBytes&) = delete;
	FileBytes& operator=(const FileBytes&) = delete;

	const char* data() const { return data_; }
	const char* end() const { return data_ + size_; }
	size_t size() const { return size_; }

   private:
	const char* data_ = nullptr;
	size_t size_ = 0;
};

/** Fills the map from its current end, in the local frame: every point is
 *  read in double, the local origin (LoadReport::origin) is subtracted, and
 *  only then is it stored as float, so georeferenced coordinates (UTM, ECEF)
 *  keep millimetres. Non-finite points and points farther than
 *  kMaxAbsCoordinate from the origin are skipped and counted. When the
 *  caller fixed no origin, the first kOriginSample points are held back and
 *  their rounded median becomes the origin (chooseLocalOrigin). The map is
 *  grown in large steps and trimmed in finish(), so the per-point path is a
 *  bounds check and four stores. */
class MapFiller
{
   public:
	MapFiller(mrpt::maps::CPointsMapXYZI& map, LoadReport& report);

	/** Room for `n` more points, so the next n add() calls never reallocate. */
	void expect(size_t n);

	void add(double x, double y, double z, float intensity)
	{
		// The count spans every observation of a .simplemap, not just this filler's.
		if ((report_.pointsRead + ++read_) % LoadReport::kProgressPoints == 0 && report_.progress)
			report_.progress(report_.pointsRead + read_);
		if (!report_.originFixed)
		{
			holdForOrigin(x, y, z, intensity);
			return;
		}
		store(x - report_.origin.x(), y - report_.origin.y(), z - report_.origin.z(), intensity);
	}

	/** Trims unused room and adds the counts to the report. */
	void finish();

	/** Points held back to choose the origin from. */
	static constexpr size_t kOriginSample = 4096;

   private:
	void store(double x, double y, double z, float intensity)
	{
		// One comparison chain rejects NaN too; the rare rejects are sorted
		// into non-finite and too-far off the fast path.
		if (!(std::fabs(x) <= kMaxAbsCoordinate && std::fabs(y) <= kMaxAbsCoordinate &&
			  std::fabs(z) <= kMaxAbsCoordinate && std::isfinite(intensity)))
		{
			skip(x, y, z, intensity);
			return;
		}
		if (next_ == capacity_) grow();
		map_.setPointFast(next_, static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
		map_.setPointColor_fast(next_, intensity, 0, 0);
		++next_;
	}
	void holdForOrigin(double x, double y, double z, float intensity);
	void fixOrigin();
	void grow();
	void skip(double x, double y, double z, float intensity);

	mrpt::maps::CPointsMapXYZI& map_;
	LoadReport& report_;
	size_t start_, next_, capacity_;
	size_t read_ = 0, nonFinite_ = 0, outOfRange_ = 0;
	std::vector<Eigen::Vector4d> held_;
};

enum class Scalar : uint8_t
{
	I8,
	U8,
	I16,
	U16,
	I32,
	U32,
	I64,
	U64,
	F32,
	F64
};

size_t scalarSize(Scalar t);

template <typename T>
inline double loadAs(const char* p)
{
	T v;
	std::memcpy(&v, p, sizeof(T));
	return static_cast<double>(v);
}

/** A stored value in double: float64 coordinates keep their precision
 *  until the local origin is subtracted. */
inline double loadScalar(Scalar t, const char* p)
{
	switch (t)
	{
		case Scalar::I8: return loadAs<int8_t>(p);
		case Scalar::U8: return loadAs<uint8_t>(p);
		case Scalar::I16: return loadAs<int16_t>(p);
		case Scalar::U16: return loadAs<uint16_t>(p);
		case Scalar::I32: return loadAs<int32_t>(p);
		case Scalar::U32: return loadAs<uint32_t>(p);
		case Scalar::I64: return loadAs<int64_t>(p);
		case Scalar::U64: return loadAs<uint64_t>(p);
		case Scalar::F32: return loadAs<float>(p);
		case Scalar::F64: return loadAs<double>(p);
	}
	return 0;
}

/** One binary field of n records: element k is at base + k * stride. Covers
 *  interleaved records (PCD binary, PLY, KITTI) and per-field blocks (PCD
 *  binary_compressed) alike. */
struct Column
{
	Scalar type = Scalar::F32;
	const char* base = nullptr;
	size_t stride = 0;
};

/** Copies n points from the x, y, z, intensity columns into the map. The
 *  caller has checked that all n records lie inside the buffer. */
void extractColumns(const Column (&xyzi)[4], size_t n, MapFiller& fill);

/** Field names accepted as intensity, in order of preference. */
const std::vector<std::string>& intensityFieldNames();

/** Index in `names` of the preferred intensity field, if any. */
std::optional<size_t> findIntensityField(const std::vector<std::string>& names);

/** Index of an exact field name, if present. */
std::optional<size_t> findField(const std::vector<std::string>& names, const std::string& wanted);

/** Throws "<file>: <place>: no intensity field (looked for ...); the fields are: a b c". */
[[noreturn]] void throwNoIntensity(const std::string& file, const std::string& place,
								   const std::vector<std::string>& fieldsPresent);

/** Lines of a text buffer, numbered from 1, with "\r\n" accepted. */
class TextLines
{
   public:
	TextLines(const char* begin, const char* end) : pos_(begin), end_(end) {}

	bool next(std::string_view& line);
	size_t lineNumber() const { return line_; }  // of the line last returned
	const char* position() const { return pos_; }  // start of the next line

   private:
	const char* pos_;
	const char* end_;
	size_t line_ = 0;
};

/** Splits on blanks, tabs and commas. Returns the number of tokens; at most
 *  `maxTokens` are stored. */
size_t splitTokens(std::string_view line, std::string_view* tokens, size_t maxTokens);
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens);

/** Decimal or scientific number, "nan"/"inf" included. */
bool parseNumber(std::string_view token, double& value);
/** A non-negative integer that fits 64 bits. */
bool parseCount(std::string_view token, uint64_t& value);

std::string lineAt(size_t lineNumber);
std::string byteAt(size_t offset);
/** `token` cut to a readable length, for messages. */
std::string quoted(std::string_view token);
std::string joined(const std::vector<std::string>& words);

/** a * b, or nullopt on 64-bit overflow. */
std::optional<uint64_t> checkedMul(uint64_t a, uint64_t b);

}  // namespace tagmap::io::detail
