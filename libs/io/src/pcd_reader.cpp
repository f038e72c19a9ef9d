// PCD v0.7 (Point Cloud Library) reader: DATA ascii, binary and
// binary_compressed, any field order, extra and multi-count fields,
// organized clouds.
#include <map>
#include <memory>

#include "reader_common.h"
#include "readers.h"
#include "tagmap/io/lzf.h"

namespace tagmap::io::detail
{
namespace
{
enum class PcdData
{
	Ascii,
	Binary,
	Compressed
};

struct PcdField
{
	std::string name;
	Scalar type = Scalar::F32;
	size_t size = 0;  // bytes of one value
	size_t count = 1;  // values per point
	size_t offset = 0;  // bytes before this field in one point record
	size_t firstValue = 0;  // index of its first value on an ascii line
};

struct PcdHeader
{
	std::vector<PcdField> fields;
	uint64_t points = 0;
	size_t pointStep = 0;  // bytes per point record
	size_t valuesPerPoint = 0;  // numbers per ascii line
	PcdData data = PcdData::Ascii;
	size_t dataStart = 0;  // byte offset of the first data byte
	size_t dataLine = 0;  // line number of the DATA line
	size_t xyzi[4] = {0, 0, 0, 0};  // field indices
};

std::optional<Scalar> pcdScalar(std::string_view type, uint64_t size)
{
	if (type == "F") return size == 4 ? Scalar::F32 : size == 8 ? std::optional(Scalar::F64) : std::nullopt;
	const bool isUnsigned = type == "U";
	if (!isUnsigned && type != "I") return std::nullopt;
	switch (size)
	{
		case 1: return isUnsigned ? Scalar::U8 : Scalar::I8;
		case 2: return isUnsigned ? Scalar::U16 : Scalar::I16;
		case 4: return isUnsigned ? Scalar::U32 : Scalar::I32;
		case 8: return isUnsigned ? Scalar::U64 : Scalar::I64;
		default: return std::nullopt;
	}
}

class PcdHeaderParser
{
   public:
	PcdHeaderParser(const std::string& path, const FileBytes& bytes) : path_(path), bytes_(bytes) {}

	PcdHeader parse()
	{
		TextLines lines(bytes_.data(), bytes_.end());
		std::string_view line;
		std::vector<std::string_view> tok;
		bool sawKeyword = false;
		while (lines.next(line))
		{
			line_ = lines.lineNumber();
			splitTokens(line, tok);
			if (tok.empty() || tok[0].front() == '#') continue;
			const std::string key(tok[0]);
			if (!sawKeyword && key != "VERSION" && key != "FIELDS")
				fail("not a PCD file: expected VERSION or FIELDS, found " + quoted(tok[0]));
			sawKeyword = true;
			const std::vector<std::string_view> values(tok.begin() + 1, tok.end());
			if (key == "DATA")
			{
				readDataKind(values);
				h_.dataStart = static_cast<size_t>(lines.position() - bytes_.data());
				h_.dataLine = line_;
				finishHeader();
				return h_;
			}
			readKeyword(key, values);
		}
		throw InputError(path_, "header", bytes_.size() == 0 ? "file is empty" : "no DATA line: not a PCD file, or its header is cut off");
	}

   private:
	[[noreturn]] void fail(const std::string& what) const { throw InputError(path_, lineAt(line_), what); }

	uint64_t count(std::string_view key, std::string_view token) const
	{
		uint64_t v;
		if (!parseCount(token, v)) fail("bad " + std::string(key) + " value " + quoted(token));
		return v;
	}

	void readKeyword(const std::string& key, const std::vector<std::string_view>& values)
	{
		if (key == "VERSION" || key == "VIEWPOINT") return;
		if (key == "FIELDS" || key == "COLUMNS")
		{
			if (values.empty()) fail("FIELDS lists no field");
			names_.assign(values.begin(), values.end());
			fieldsLine_ = line_;
			return;
		}
		if (key == "SIZE" || key == "TYPE" || key == "COUNT")
		{
			perField_[key] = {values, line_};
			return;
		}
		if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS")
		{
			if (values.size() != 1) fail(key + " needs exactly one value");
			scalars_[key] = count(key, values[0]);
			return;
		}
		fail("unknown header keyword " + quoted(key));
	}

	void readDataKind(const std::vector<std::string_view>& values)
	{
		if (values.size() != 1) fail("DATA needs one of ascii, binary, binary_compressed");
		if (values[0] == "ascii") h_.data = PcdData::Ascii;
		else if (values[0] == "binary") h_.data = PcdData::Binary;
		else if (values[0] == "binary_compressed") h_.data = PcdData::Compressed;
		else fail("unknown DATA kind " + quoted(values[0]) + " (expected ascii, binary or binary_compressed)");
	}

	const std::vector<std::string_view>& perField(const std::string& key, bool required)
	{
		static const std::vector<std::string_view> none;
		const auto it = perField_.find(key);
		if (it == perField_.end())
		{
			if (required) throw InputError(path_, "header", "no " + key + " line");
			return none;
		}
		if (it->second.values.size() != names_.size())
			throw InputError(path_, lineAt(it->second.line),
							 key + " has " + std::to_string(it->second.values.size()) + " entries but FIELDS has " +
								 std::to_string(names_.size()));
		return it->second.values;
	}

	void finishHeader()
	{
		if (names_.empty()) throw InputError(path_, "header", "no FIELDS line");
		const auto& sizes = perField("SIZE", true);
		const auto& types = perField("TYPE", true);
		const auto& counts = perField("COUNT", false);
		size_t step = 0, values = 0;
		for (size_t k = 0; k < names_.size(); ++k)
		{
			PcdField f;
			f.name = names_[k];
			line_ = perField_["SIZE"].line;
			const uint64_t size = count("SIZE", sizes[k]);
			const auto type = pcdScalar(types[k], size);
			if (!type)
				throw InputError(path_, "field " + f.name,
								 "TYPE " + std::string(types[k]) + " with SIZE " + std::to_string(size) +
									 " is not a valid PCD type (F 4/8, U or I 1/2/4/8)");
			f.type = *type;
			f.size = static_cast<size_t>(size);
			if (!counts.empty())
			{
				line_ = perField_["COUNT"].line;
				const uint64_t c = count("COUNT", counts[k]);
				// A larger count can only be a corrupt header; it would also
				// overflow the record size computations below.
				if (c == 0 || c > (1u << 24)) throw InputError(path_, "field " + f.name, "COUNT " + std::to_string(c) + " is out of range");
				f.count = static_cast<size_t>(c);
			}
			f.offset = step;
			f.firstValue = values;
			step += f.size * f.count;
			values += f.count;
			h_.fields.push_back(f);
		}
		h_.pointStep = step;
		h_.valuesPerPoint = values;
		findXyzi();
		pointCount();
	}

	void findXyzi()
	{
		const char* axes[3] = {"x", "y", "z"};
		for (int a = 0; a < 3; ++a)
		{
			const auto idx = findField(names_, axes[a]);
			if (!idx) throw InputError(path_, lineAt(fieldsLine_), std::string("no ") + axes[a] + " field; the fields are: " + joined(names_));
			h_.xyzi[a] = *idx;
		}
		const auto idx = findIntensityField(names_);
		if (!idx) throwNoIntensity(path_, lineAt(fieldsLine_), names_);
		h_.xyzi[3] = *idx;
		for (size_t k : h_.xyzi)
			if (h_.fields[k].count != 1)
				throw InputError(path_, "field " + h_.fields[k].name, "has COUNT " + std::to_string(h_.fields[k].count) + ", expected 1");
	}

	void pointCount()
	{
		if (!scalars_.count("WIDTH")) throw InputError(path_, "header", "no WIDTH line");
		const uint64_t width = scalars_["WIDTH"];
		const uint64_t height = scalars_.count("HEIGHT") ? scalars_["HEIGHT"] : 1;
		const auto wh = checkedMul(width, height);
		if (!wh) throw InputError(path_, "header", "WIDTH x HEIGHT overflows");
		h_.points = scalars_.count("POINTS") ? scalars_["POINTS"] : *wh;
		if (h_.points != *wh)
			throw InputError(path_, "header",
							 "POINTS " + std::to_string(h_.points) + " does not match WIDTH x HEIGHT = " + std::to_string(width) + " x " +
								 std::to_string(height));
	}

	struct PerField
	{
		std::vector<std::string_view> values;
		size_t line = 0;
	};

	const std::string& path_;
	const FileBytes& bytes_;
	PcdHeader h_;
	size_t line_ = 0, fieldsLine_ = 0;
	std::vector<std::string> names_;
	std::map<std::string, PerField> perField_;
	std::map<std::string, uint64_t> scalars_;
};

Column columnOf(const PcdField& f, const char* base, size_t stride) { return Column{f.type, base, stride}; }

void readAscii(const std::string& path, const FileBytes& bytes, const PcdHeader& h, MapFiller& fill)
{
	const size_t available = bytes.size() - h.dataStart;
	// Every value takes at least a digit and a separator: a header claiming
	// more points than that cannot be right, so reserve no more than fits.
	fill.expect(static_cast<size_t>(std::min<uint64_t>(h.points, available / (2 * h.valuesPerPoint) + 1)));
	TextLines lines(bytes.data() + h.dataStart, bytes.end());
	std::vector<std::string_view> tok;
	std::string_view line;
	uint64_t done = 0;
	size_t tokenOf[4];
	for (int a = 0; a < 4; ++a) tokenOf[a] = h.fields[h.xyzi[a]].firstValue;
	while (lines.next(line))
	{
		const size_t lineNo = h.dataLine + lines.lineNumber();
		splitTokens(line, tok);
		if (tok.empty()) continue;
		if (done == h.points) throw InputError(path, lineAt(lineNo), "more data lines than POINTS " + std::to_string(h.points));
		if (tok.size() != h.valuesPerPoint)
			throw InputError(path, lineAt(lineNo),
							 std::to_string(tok.size()) + " values, the header declares " + std::to_string(h.valuesPerPoint) + " per point");
		double v[4];
		for (int a = 0; a < 4; ++a)
			if (!parseNumber(tok[tokenOf[a]], v[a]))
				throw InputError(path, lineAt(lineNo), "field " + h.fields[h.xyzi[a]].name + ": " + quoted(tok[tokenOf[a]]) + " is not a number");
		fill.add(v[0], v[1], v[2], static_cast<float>(v[3]));
		++done;
	}
	if (done != h.points)
		throw InputError(path, lineAt(h.dataLine + lines.lineNumber()),
						 "file ends after " + std::to_string(done) + " of " + std::to_string(h.points) + " points");
}

size_t dataBytes(const std::string& path, const PcdHeader& h)
{
	const auto need = checkedMul(h.points, h.pointStep);
	if (!need || *need > SIZE_MAX / 2) throw InputError(path, "header", "POINTS " + std::to_string(h.points) + " is absurdly large");
	return static_cast<size_t>(*need);
}

void readBinary(const std::string& path, const FileBytes& bytes, const PcdHeader& h, MapFiller& fill)
{
	const size_t need = dataBytes(path, h);
	const size_t available = bytes.size() - h.dataStart;
	if (need > available)
		throw InputError(path, byteAt(h.dataStart),
						 "truncated: " + std::to_string(h.points) + " points x " + std::to_string(h.pointStep) + " bytes need " +
							 std::to_string(need) + " bytes of data, the file has " + std::to_string(available));
	const char* base = bytes.data() + h.dataStart;
	Column c[4];
	for (int a = 0; a < 4; ++a)
	{
		const PcdField& f = h.fields[h.xyzi[a]];
		c[a] = columnOf(f, base + f.offset, h.pointStep);
	}
	extractColumns(c, static_cast<size_t>(h.points), fill);
}

// binary_compressed: two uint32 (compressed, uncompressed size), then one LZF
// block that decodes to the fields one after another, each as an array over
// all points (structure of arrays), not as interleaved records.
void readCompressed(const std::string& path, const FileBytes& bytes, const PcdHeader& h, MapFiller& fill)
{
	const size_t need = dataBytes(path, h);
	const size_t available = bytes.size() - h.dataStart;
	if (available < 8) throw InputError(path, byteAt(h.dataStart), "truncated: the compressed-size words are missing");
	uint32_t sizes[2];
	std::memcpy(sizes, bytes.data() + h.dataStart, 8);
	const size_t compressed = sizes[0], uncompressed = sizes[1];
	if (compressed > available - 8)
		throw InputError(path, byteAt(h.dataStart),
						 "truncated: compressed block of " + std::to_string(compressed) + " bytes, the file has " + std::to_string(available - 8));
	if (uncompressed != need)
		throw InputError(path, byteAt(h.dataStart + 4),
						 "uncompressed size " + std::to_string(uncompressed) + " does not match POINTS x point size = " + std::to_string(need));
	// One LZF byte yields at most 88 output bytes (a 3-byte reference of 264);
	// a larger claim is corrupt and must not be allocated.
	if (uncompressed / 88 > compressed)
		throw InputError(path, byteAt(h.dataStart), "uncompressed size " + std::to_string(uncompressed) + " is impossible for " + std::to_string(compressed) + " LZF bytes");
	if (h.points == 0) return;
	std::unique_ptr<uint8_t[]> buffer(new uint8_t[uncompressed]);
	try
	{
		lzfDecompress(reinterpret_cast<const uint8_t*>(bytes.data() + h.dataStart + 8), compressed, buffer.get(), uncompressed);
	}
	catch (const LzfError& e)
	{
		throw InputError(path, byteAt(h.dataStart + 8 + e.offset), std::string("corrupt LZF data: ") + e.what());
	}
	const char* base = reinterpret_cast<const char*>(buffer.get());
	Column c[4];
	for (int a = 0; a < 4; ++a)
	{
		const PcdField& f = h.fields[h.xyzi[a]];
		c[a] = columnOf(f, base + f.offset * h.points, f.size * f.count);
	}
	extractColumns(c, static_cast<size_t>(h.points), fill);
}

}  // namespace

void readPcd(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const FileBytes bytes(path);
	const PcdHeader h = PcdHeaderParser(path, bytes).parse();
	report.intensityField = h.fields[h.xyzi[3]].name;
	MapFiller fill(out, report);
	switch (h.data)
	{
		case PcdData::Ascii:
			report.format = "pcd-ascii";
			readAscii(path, bytes, h, fill);
			break;
		case PcdData::Binary:
			report.format = "pcd-binary";
			readBinary(path, bytes, h, fill);
			break;
		case PcdData::Compressed:
			report.format = "pcd-binary_compressed";
			readCompressed(path, bytes, h, fill);
			break;
	}
	fill.finish();
}

}  // namespace tagmap::io::detail
