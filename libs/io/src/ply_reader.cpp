// PLY reader (ascii and binary_little_endian): the "vertex" element's x, y, z
// and intensity-like property; every other property and element, list
// properties included, is stepped over.
#include <algorithm>

#include "reader_common.h"
#include "readers.h"

namespace tagmap::io::detail
{
namespace
{
struct PlyProperty
{
	std::string name;
	Scalar type = Scalar::F32;
	bool isList = false;
	Scalar countType = Scalar::U8;  // lists: type of the length prefix
};

struct PlyElement
{
	std::string name;
	uint64_t count = 0;
	size_t line = 0;
	std::vector<PlyProperty> props;

	bool fixedSize() const
	{
		return std::none_of(props.begin(), props.end(), [](const PlyProperty& p) { return p.isList; });
	}
	size_t recordSize() const
	{
		size_t s = 0;
		for (const auto& p : props) s += scalarSize(p.type);
		return s;
	}
	std::vector<std::string> propertyNames() const
	{
		std::vector<std::string> names;
		for (const auto& p : props) names.push_back(p.name);
		return names;
	}
};

struct PlyHeader
{
	bool binary = false;
	std::vector<PlyElement> elements;
	size_t vertex = 0;  // index of the vertex element
	size_t xyzi[4] = {0, 0, 0, 0};  // property indices in the vertex element
	size_t dataStart = 0;
	size_t dataLine = 0;  // line number of end_header
};

std::optional<Scalar> plyScalar(std::string_view t)
{
	if (t == "char" || t == "int8") return Scalar::I8;
	if (t == "uchar" || t == "uint8") return Scalar::U8;
	if (t == "short" || t == "int16") return Scalar::I16;
	if (t == "ushort" || t == "uint16") return Scalar::U16;
	if (t == "int" || t == "int32") return Scalar::I32;
	if (t == "uint" || t == "uint32") return Scalar::U32;
	if (t == "float" || t == "float32") return Scalar::F32;
	if (t == "double" || t == "float64") return Scalar::F64;
	return std::nullopt;
}

PlyHeader parseHeader(const std::string& path, const FileBytes& bytes)
{
	TextLines lines(bytes.data(), bytes.end());
	std::string_view line;
	if (!lines.next(line) || line != "ply")
		throw InputError(path, lineAt(1), bytes.size() == 0 ? "file is empty" : "not a PLY file (it does not start with 'ply')");
	PlyHeader h;
	bool sawFormat = false;
	std::vector<std::string_view> tok;
	auto fail = [&](const std::string& what) { throw InputError(path, lineAt(lines.lineNumber()), what); };
	auto scalarOf = [&](std::string_view t) {
		const auto s = plyScalar(t);
		if (!s) fail("unknown property type " + quoted(t));
		return *s;
	};
	while (lines.next(line))
	{
		splitTokens(line, tok);
		if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
		if (tok[0] == "format")
		{
			if (tok.size() < 2) fail("format line without a format");
			if (tok[1] == "ascii") h.binary = false;
			else if (tok[1] == "binary_little_endian") h.binary = true;
			else if (tok[1] == "binary_big_endian") fail("binary_big_endian PLY is not supported; convert it to little endian or ascii");
			else fail("unknown format " + quoted(tok[1]));
			sawFormat = true;
		}
		else if (tok[0] == "element")
		{
			uint64_t n = 0;  // fail() throws, but clang cannot see that through the lambda
			if (tok.size() != 3 || !parseCount(tok[2], n)) fail("expected 'element <name> <count>'");
			h.elements.push_back(PlyElement{std::string(tok[1]), n, lines.lineNumber(), {}});
		}
		else if (tok[0] == "property")
		{
			if (h.elements.empty()) fail("property before any element");
			PlyProperty p;
			if (tok.size() == 5 && tok[1] == "list")
			{
				p.isList = true;
				p.countType = scalarOf(tok[2]);
				if (p.countType == Scalar::F32 || p.countType == Scalar::F64) fail("list length type must be an integer type");
				p.type = scalarOf(tok[3]);
				p.name = tok[4];
			}
			else if (tok.size() == 3)
			{
				p.type = scalarOf(tok[1]);
				p.name = tok[2];
			}
			else
				fail("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
			h.elements.back().props.push_back(p);
		}
		else if (tok[0] == "end_header")
		{
			if (!sawFormat) fail("no format line before end_header");
			h.dataStart = static_cast<size_t>(lines.position() - bytes.data());
			h.dataLine = lines.lineNumber();
			break;
		}
		else
			fail("unknown header keyword " + quoted(tok[0]));
	}
	if (h.dataStart == 0) throw InputError(path, "header", "no end_header line: the header is cut off");

	const auto vertex = std::find_if(h.elements.begin(), h.elements.end(), [](const PlyElement& e) { return e.name == "vertex"; });
	if (vertex == h.elements.end()) throw InputError(path, "header", "no vertex element");
	h.vertex = static_cast<size_t>(vertex - h.elements.begin());
	const auto names = vertex->propertyNames();
	const char* axes[3] = {"x", "y", "z"};
	for (int a = 0; a < 3; ++a)
	{
		const auto idx = findField(names, axes[a]);
		if (!idx) throw InputError(path, lineAt(vertex->line), std::string("vertex has no ") + axes[a] + " property; its properties are: " + joined(names));
		h.xyzi[a] = *idx;
	}
	const auto idx = findIntensityField(names);
	if (!idx) throwNoIntensity(path, lineAt(vertex->line), names);
	h.xyzi[3] = *idx;
	for (size_t k : h.xyzi)
		if (vertex->props[k].isList) throw InputError(path, "property " + vertex->props[k].name, "is a list, expected a single number");
	return h;
}

// ---- binary ---------------------------------------------------------------

class BinaryWalker
{
   public:
	BinaryWalker(const std::string& path, const FileBytes& bytes, size_t start) : path_(path), bytes_(bytes), pos_(start) {}

	size_t position() const { return pos_; }

	/** Steps over every record of `e`. */
	void skipElement(const PlyElement& e)
	{
		if (e.fixedSize())
		{
			const auto total = checkedMul(e.count, e.recordSize());
			if (!total || *total > bytes_.size() - pos_) truncated(e, 0);
			pos_ += static_cast<size_t>(*total);
			return;
		}
		// Each record has at least one list length, so the loop is bounded
		// by the file size whatever count the header claims.
		for (uint64_t r = 0; r < e.count; ++r)
			for (const auto& p : e.props) skipProperty(e, r, p);
	}

	/** Reads one property value of record r (pos_ at the property). */
	double value(const PlyElement& e, uint64_t r, const PlyProperty& p)
	{
		need(e, r, scalarSize(p.type));
		const double v = loadScalar(p.type, bytes_.data() + pos_);
		pos_ += scalarSize(p.type);
		return v;
	}

	void skipProperty(const PlyElement& e, uint64_t r, const PlyProperty& p)
	{
		if (!p.isList)
		{
			need(e, r, scalarSize(p.type));
			pos_ += scalarSize(p.type);
			return;
		}
		const uint64_t length = listLength(e, r, p);
		const auto bytes = checkedMul(length, scalarSize(p.type));
		if (!bytes || *bytes > bytes_.size() - pos_) truncated(e, r);
		pos_ += static_cast<size_t>(*bytes);
	}

	[[noreturn]] void truncated(const PlyElement& e, uint64_t r) const
	{
		throw InputError(path_, byteAt(pos_),
						 "truncated in element " + e.name + " (record " + std::to_string(r) + " of " + std::to_string(e.count) + ")");
	}

   private:
	// Read as an integer, not through float: lengths above 2^24 must stay exact.
	uint64_t listLength(const PlyElement& e, uint64_t r, const PlyProperty& p)
	{
		const size_t at = pos_;
		need(e, r, scalarSize(p.countType));
		const char* q = bytes_.data() + pos_;
		pos_ += scalarSize(p.countType);
		int64_t n = 0;
		switch (p.countType)
		{
			case Scalar::I8: n = intAs<int8_t>(q); break;
			case Scalar::U8: n = intAs<uint8_t>(q); break;
			case Scalar::I16: n = intAs<int16_t>(q); break;
			case Scalar::U16: n = intAs<uint16_t>(q); break;
			case Scalar::I32: n = intAs<int32_t>(q); break;
			default: n = intAs<uint32_t>(q); break;  // the header allows no other type
		}
		if (n < 0) throw InputError(path_, byteAt(at), "element " + e.name + ": negative list length");
		return static_cast<uint64_t>(n);
	}

	template <typename T>
	static int64_t intAs(const char* q)
	{
		T v;
		std::memcpy(&v, q, sizeof v);
		return static_cast<int64_t>(v);
	}

	void need(const PlyElement& e, uint64_t r, size_t n) const
	{
		if (n > bytes_.size() - pos_) truncated(e, r);
	}

	const std::string& path_;
	const FileBytes& bytes_;
	size_t pos_;
};

void readBinaryVertices(const PlyHeader& h, const PlyElement& v, BinaryWalker& walk, const FileBytes& bytes, MapFiller& fill)
{
	if (v.fixedSize())
	{
		const size_t stride = v.recordSize();
		const auto total = checkedMul(v.count, stride);
		if (!total || *total > bytes.size() - walk.position()) walk.truncated(v, 0);
		std::vector<size_t> offset(v.props.size(), 0);
		for (size_t k = 1; k < v.props.size(); ++k) offset[k] = offset[k - 1] + scalarSize(v.props[k - 1].type);
		Column c[4];
		for (int a = 0; a < 4; ++a)
			c[a] = Column{v.props[h.xyzi[a]].type, bytes.data() + walk.position() + offset[h.xyzi[a]], stride};
		extractColumns(c, static_cast<size_t>(v.count), fill);
		return;
	}
	// Lists inside the vertex element: records differ in length, so walk them.
	for (uint64_t r = 0; r < v.count; ++r)
	{
		double xyzi[4] = {0, 0, 0, 0};
		for (size_t k = 0; k < v.props.size(); ++k)
		{
			const auto slot = std::find(std::begin(h.xyzi), std::end(h.xyzi), k);
			if (slot == std::end(h.xyzi)) walk.skipProperty(v, r, v.props[k]);
			else xyzi[slot - std::begin(h.xyzi)] = walk.value(v, r, v.props[k]);
		}
		fill.add(xyzi[0], xyzi[1], xyzi[2], static_cast<float>(xyzi[3]));
	}
}

void readBinary(const std::string& path, const FileBytes& bytes, const PlyHeader& h, MapFiller& fill)
{
	BinaryWalker walk(path, bytes, h.dataStart);
	// Elements after the vertices are never needed, so never read.
	for (size_t k = 0; k < h.vertex; ++k) walk.skipElement(h.elements[k]);
	readBinaryVertices(h, h.elements[h.vertex], walk, bytes, fill);
}

// ---- ascii ----------------------------------------------------------------

void readAscii(const std::string& path, const FileBytes& bytes, const PlyHeader& h, MapFiller& fill)
{
	TextLines lines(bytes.data() + h.dataStart, bytes.end());
	std::string_view line;
	std::vector<std::string_view> tok;
	auto lineNo = [&] { return h.dataLine + lines.lineNumber(); };
	auto nextRecord = [&](const PlyElement& e, uint64_t r) {
		do
		{
			if (!lines.next(line))
				throw InputError(path, lineAt(lineNo() + 1),
								 "file ends in element " + e.name + " after " + std::to_string(r) + " of " + std::to_string(e.count) + " records");
			splitTokens(line, tok);
		} while (tok.empty());
	};
	for (size_t k = 0; k < h.vertex; ++k)
		for (uint64_t r = 0; r < h.elements[k].count; ++r) nextRecord(h.elements[k], r);

	const PlyElement& v = h.elements[h.vertex];
	const size_t available = bytes.size() - static_cast<size_t>(lines.position() - bytes.data());
	fill.expect(static_cast<size_t>(std::min<uint64_t>(v.count, available / (2 * v.props.size()) + 1)));
	for (uint64_t r = 0; r < v.count; ++r)
	{
		nextRecord(v, r);
		double xyzi[4] = {0, 0, 0, 0};
		size_t t = 0;
		for (size_t k = 0; k < v.props.size(); ++k)
		{
			if (t >= tok.size()) throw InputError(path, lineAt(lineNo()), "too few values for the vertex properties");
			if (v.props[k].isList)
			{
				uint64_t n;
				if (!parseCount(tok[t], n) || n > tok.size()) throw InputError(path, lineAt(lineNo()), "bad list length " + quoted(tok[t]));
				t += 1 + static_cast<size_t>(n);
				continue;
			}
			const auto slot = std::find(std::begin(h.xyzi), std::end(h.xyzi), k);
			if (slot != std::end(h.xyzi) && !parseNumber(tok[t], xyzi[slot - std::begin(h.xyzi)]))
				throw InputError(path, lineAt(lineNo()), "property " + v.props[k].name + ": " + quoted(tok[t]) + " is not a number");
			++t;
		}
		if (t != tok.size())
			throw InputError(path, lineAt(lineNo()), std::to_string(tok.size()) + " values, the vertex properties need " + std::to_string(t));
		fill.add(xyzi[0], xyzi[1], xyzi[2], static_cast<float>(xyzi[3]));
	}
}

}  // namespace

void readPly(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const FileBytes bytes(path);
	const PlyHeader h = parseHeader(path, bytes);
	report.format = h.binary ? "ply-binary" : "ply-ascii";
	report.intensityField = h.elements[h.vertex].props[h.xyzi[3]].name;
	MapFiller fill(out, report);
	if (h.binary) readBinary(path, bytes, h, fill);
	else readAscii(path, bytes, h, fill);
	fill.finish();
}

}  // namespace tagmap::io::detail
