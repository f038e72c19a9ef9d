#include "reader_common.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>

namespace tagmap::io::detail
{
FileBytes::FileBytes(const std::string& path)
{
	const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
	if (fd < 0) throw InputError(path, "", std::string("cannot open: ") + std::strerror(errno));
	struct stat st{};
	if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
	{
		::close(fd);
		throw InputError(path, "", "is not a regular file");
	}
	size_ = static_cast<size_t>(st.st_size);
	if (size_ > 0)
	{
		// No MAP_POPULATE: measured slower here, the kernel's fault-around
		// already maps cached file pages in batches.
		void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
		if (p == MAP_FAILED)
		{
			const int err = errno;
			::close(fd);
			throw InputError(path, "", std::string("cannot map into memory: ") + std::strerror(err));
		}
		::madvise(p, size_, MADV_SEQUENTIAL);
		data_ = static_cast<const char*>(p);
	}
	::close(fd);
}

FileBytes::~FileBytes()
{
	if (data_) ::munmap(const_cast<char*>(data_), size_);
}

MapFiller::MapFiller(mrpt::maps::CPointsMapXYZI& map, LoadReport& report)
	: map_(map), report_(report), start_(map.size()), next_(map.size()), capacity_(map.size())
{
}

void MapFiller::expect(size_t n)
{
	if (capacity_ - next_ >= n) return;
	capacity_ = next_ + n;
	map_.resize(capacity_);
}

void MapFiller::holdForOrigin(double x, double y, double z, float intensity)
{
	held_.emplace_back(x, y, z, intensity);
	if (held_.size() == kOriginSample) fixOrigin();
}

void MapFiller::fixOrigin()
{
	std::vector<Eigen::Vector3d> sample;
	sample.reserve(held_.size());
	for (const auto& h : held_) sample.push_back(h.head<3>());
	report_.origin = chooseLocalOrigin(std::move(sample));
	report_.originFixed = true;
	for (const auto& h : held_)
		store(h.x() - report_.origin.x(), h.y() - report_.origin.y(), h.z() - report_.origin.z(), static_cast<float>(h.w()));
	held_ = {};
}

void MapFiller::skip(double x, double y, double z, float intensity)
{
	if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && std::isfinite(intensity)) ++outOfRange_;
	else ++nonFinite_;
}

void MapFiller::grow() { expect(std::max<size_t>(4096, (next_ - start_) / 2)); }

void MapFiller::finish()
{
	if (!report_.originFixed) fixOrigin();
	map_.resize(next_);
	// setPointFast() leaves caches (kd-tree, bounding box) to the caller.
	map_.mark_as_modified();
	report_.pointsRead += read_;
	report_.pointsKept += next_ - start_;
	report_.nonFiniteSkipped += nonFinite_;
	report_.outOfRangeSkipped += outOfRange_;
	start_ = capacity_ = next_;
	read_ = nonFinite_ = outOfRange_ = 0;
}

size_t scalarSize(Scalar t)
{
	switch (t)
	{
		case Scalar::I8:
		case Scalar::U8: return 1;
		case Scalar::I16:
		case Scalar::U16: return 2;
		case Scalar::I32:
		case Scalar::U32:
		case Scalar::F32: return 4;
		case Scalar::I64:
		case Scalar::U64:
		case Scalar::F64: return 8;
	}
	return 0;
}

void extractColumns(const Column (&c)[4], size_t n, MapFiller& fill)
{
	fill.expect(n);
	const bool allFloat = std::all_of(std::begin(c), std::end(c), [](const Column& k) { return k.type == Scalar::F32; });
	// The all-float case is nearly every real file; keeping it free of the
	// per-value type switch lets it run at memory speed.
	if (allFloat)
	{
		for (size_t k = 0; k < n; ++k)
			fill.add(loadAs<float>(c[0].base + k * c[0].stride), loadAs<float>(c[1].base + k * c[1].stride),
					 loadAs<float>(c[2].base + k * c[2].stride), static_cast<float>(loadAs<float>(c[3].base + k * c[3].stride)));
		return;
	}
	for (size_t k = 0; k < n; ++k)
		fill.add(loadScalar(c[0].type, c[0].base + k * c[0].stride), loadScalar(c[1].type, c[1].base + k * c[1].stride),
				 loadScalar(c[2].type, c[2].base + k * c[2].stride),
				 static_cast<float>(loadScalar(c[3].type, c[3].base + k * c[3].stride)));
}

const std::vector<std::string>& intensityFieldNames()
{
	static const std::vector<std::string> names{"intensity", "reflectivity", "scalar_Intensity", "i"};
	return names;
}

namespace
{
bool equalsNoCase(const std::string& a, const std::string& b)
{
	return a.size() == b.size() &&
		   std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}
}  // namespace

std::optional<size_t> findIntensityField(const std::vector<std::string>& names)
{
	for (const auto& wanted : intensityFieldNames())
		for (size_t k = 0; k < names.size(); ++k)
			if (equalsNoCase(names[k], wanted)) return k;
	return std::nullopt;
}

std::optional<size_t> findField(const std::vector<std::string>& names, const std::string& wanted)
{
	const auto it = std::find(names.begin(), names.end(), wanted);
	if (it == names.end()) return std::nullopt;
	return static_cast<size_t>(it - names.begin());
}

void throwNoIntensity(const std::string& file, const std::string& place, const std::vector<std::string>& fieldsPresent)
{
	throw InputError(file, place,
					 "no intensity field (looked for " + joined(intensityFieldNames()) + "); the fields are: " +
						 (fieldsPresent.empty() ? std::string("(none)") : joined(fieldsPresent)));
}

bool TextLines::next(std::string_view& line)
{
	if (pos_ >= end_) return false;
	const char* nl = static_cast<const char*>(std::memchr(pos_, '\n', static_cast<size_t>(end_ - pos_)));
	const char* stop = nl ? nl : end_;
	size_t len = static_cast<size_t>(stop - pos_);
	if (len > 0 && pos_[len - 1] == '\r') --len;
	line = std::string_view(pos_, len);
	pos_ = nl ? nl + 1 : end_;
	++line_;
	return true;
}

namespace
{
inline bool isSeparator(char ch) { return ch == ' ' || ch == '\t' || ch == ',' || ch == '\r'; }
}  // namespace

size_t splitTokens(std::string_view line, std::string_view* tokens, size_t maxTokens)
{
	size_t count = 0, k = 0;
	const size_t n = line.size();
	while (k < n)
	{
		while (k < n && isSeparator(line[k])) ++k;
		if (k >= n) break;
		const size_t begin = k;
		while (k < n && !isSeparator(line[k])) ++k;
		if (count < maxTokens) tokens[count] = line.substr(begin, k - begin);
		++count;
	}
	return count;
}

void splitTokens(std::string_view line, std::vector<std::string_view>& tokens)
{
	tokens.resize(std::max<size_t>(tokens.capacity(), 16));
	size_t count;
	while ((count = splitTokens(line, tokens.data(), tokens.size())) > tokens.size()) tokens.resize(count);
	tokens.resize(count);
}

bool parseNumber(std::string_view token, double& value)
{
	if (!token.empty() && token.front() == '+') token.remove_prefix(1);
	if (token.empty()) return false;
	const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
	return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

bool parseCount(std::string_view token, uint64_t& value)
{
	if (token.empty()) return false;
	const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
	return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

std::string lineAt(size_t lineNumber) { return "line " + std::to_string(lineNumber); }
std::string byteAt(size_t offset) { return "byte offset " + std::to_string(offset); }

std::string quoted(std::string_view token)
{
	std::string s(token.substr(0, 40));
	for (char& ch : s)
		if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
	return "'" + s + (token.size() > 40 ? "...'" : "'");
}

std::string joined(const std::vector<std::string>& words)
{
	std::string s;
	for (const auto& w : words) s += (s.empty() ? "" : " ") + w;
	return s;
}

std::optional<uint64_t> checkedMul(uint64_t a, uint64_t b)
{
	uint64_t r;
	if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
	return r;
}

}  // namespace tagmap::io::detail
