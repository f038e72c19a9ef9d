#include "tagmap/yaml_text.h"

#include <unistd.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>

#include "tagmap/errors.h"

namespace tagmap
{
namespace
{
/** Offset of the first byte that is not part of valid UTF-8 (RFC 3629: no
 *  overlong forms, no surrogates, nothing above U+10FFFF), or npos. */
size_t firstInvalidUtf8(const std::string& text)
{
	const auto* p = reinterpret_cast<const unsigned char*>(text.data());
	const size_t n = text.size();
	for (size_t i = 0; i < n;)
	{
		const unsigned c = p[i];
		if (c < 0x80)
		{
			i++;
			continue;
		}
		// Length and the allowed range of the second byte, by lead byte.
		size_t len = 0;
		unsigned lo = 0x80, hi = 0xbf;
		if (c >= 0xc2 && c <= 0xdf) len = 2;
		else if (c >= 0xe0 && c <= 0xef) len = 3, lo = c == 0xe0 ? 0xa0 : 0x80, hi = c == 0xed ? 0x9f : 0xbf;
		else if (c >= 0xf0 && c <= 0xf4) len = 4, lo = c == 0xf0 ? 0x90 : 0x80, hi = c == 0xf4 ? 0x8f : 0xbf;
		if (len == 0 || len > n - i || p[i + 1] < lo || p[i + 1] > hi) return i;
		for (size_t k = 2; k < len; k++)
			if ((p[i + k] & 0xc0) != 0x80) return i;
		i += len;
	}
	return std::string::npos;
}

/** Refuses text that is not UTF-8: YAML is Unicode, and libfyaml (as of
 *  Debian 12) loops forever on some invalid bytes, e.g. right after '%'. */
void checkUtf8(const std::string& text, const std::string& file)
{
	const size_t bad = firstInvalidUtf8(text);
	if (bad == std::string::npos) return;
	const size_t lineStart = text.rfind('\n', bad == 0 ? 0 : bad - 1);
	const size_t line = 1 + static_cast<size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n'));
	const size_t column = lineStart == std::string::npos || bad == 0 ? bad + 1 : bad - lineStart;
	throw InputError(file, "",
					 "not valid YAML: line " + std::to_string(line) + ", column " + std::to_string(column) +
						 ": not UTF-8 text (byte offset " + std::to_string(bad) + ")");
}
/** Refuses flow collections nested deeper than any configuration or scene
 *  needs: libfyaml (as of Debian 12) crashes in its own error report on some
 *  invalid text nested about a thousand deep (fuzz_config: 1266 levels of
 *  '{' with a stray quote; 133 levels of the same text were reported
 *  cleanly). Brackets are counted as they come, quoted or not: a real file
 *  stays far below the limit either way. */
void checkNesting(const std::string& text, const std::string& file)
{
	constexpr int kMaxDepth = 64;
	int depth = 0;
	size_t line = 1;
	for (const char c : text)
	{
		if (c == '\n') line++;
		else if (c == '{' || c == '[') depth++;
		else if ((c == '}' || c == ']') && depth > 0) depth--;
		if (depth > kMaxDepth)
			throw InputError(file, "", "not valid YAML: line " + std::to_string(line) + ": brackets nested deeper than " +
										   std::to_string(kMaxDepth) + " levels");
	}
}
}  // namespace

mrpt::containers::yaml parseYamlText(const std::string& text, const std::string& file)
{
	checkUtf8(text, file);
	checkNesting(text, file);
	// MRPT 2.5.8 hands libfyaml's syntax errors to stderr and mostly returns
	// a partial tree instead of throwing, which would turn a typo into a
	// confusing "missing key" later. So stderr is captured while parsing and
	// libfyaml's first "error:" line becomes the InputError.
	static std::mutex m;
	std::lock_guard<std::mutex> lock(m);
	std::string diagnostics, thrown;
	mrpt::containers::yaml doc;
	std::fflush(stderr);
	FILE* capture = std::tmpfile();
	const int saved = capture ? dup(2) : -1;
	if (saved >= 0) dup2(fileno(capture), 2);
	try
	{
		doc = mrpt::containers::yaml::FromText(text);
	}
	catch (const std::exception& e)
	{
		thrown = e.what();
	}
	if (saved >= 0)
	{
		std::fflush(stderr);
		dup2(saved, 2);
		close(saved);
		std::rewind(capture);
		char buf[4096];
		size_t n;
		while ((n = std::fread(buf, 1, sizeof buf, capture)) > 0) diagnostics.append(buf, n);
	}
	if (capture) std::fclose(capture);

	std::istringstream lines(diagnostics);
	std::string line;
	static const std::regex kFy(R"(.*:(\d+):(\d+): error: (.*))");
	std::smatch mm;
	while (std::getline(lines, line))
		if (std::regex_match(line, mm, kFy))
			throw InputError(file, "", "not valid YAML: line " + mm[1].str() + ", column " + mm[2].str() + ": " + mm[3].str());
	if (!thrown.empty()) throw InputError(file, "", "not valid YAML");
	return doc;
}

mrpt::containers::yaml readYamlFile(const std::string& path)
{
	// A folder opens as a stream and reads as empty: refuse it by name.
	if (std::filesystem::is_directory(path)) throw InputError(path, "", "is a folder, expected a YAML file");
	std::ifstream in(path, std::ios::binary);
	if (!in) throw InputError(path, "", std::string("cannot open: ") + std::strerror(errno));
	std::ostringstream text;
	text << in.rdbuf();
	return parseYamlText(text.str(), path);
}

namespace
{
template <typename T>
bool printIf(const std::any& value, std::ostream& out)
{
	const auto* v = std::any_cast<T>(&value);
	if (v) out << *v;
	return v != nullptr;
}
}  // namespace

std::string yamlScalarText(const mrpt::containers::yaml& node)
{
	if (!node.isScalar()) throw std::invalid_argument("expected a single value, not a map or list");
	const auto& s = node.asScalar();
	if (!s.has_value()) return "null";  // YAML's null, ~ or an empty value
	if (const auto* v = std::any_cast<std::string>(&s)) return *v;
	if (const auto* v = std::any_cast<const char*>(&s)) return *v;
	if (const auto* v = std::any_cast<bool>(&s)) return *v ? "true" : "false";
	// Trees built in code (PipelineParams::toYaml) store typed values.
	std::ostringstream out;
	out.precision(17);
	const bool printed = printIf<double>(s, out) || printIf<float>(s, out) || printIf<int>(s, out) ||
						 printIf<unsigned>(s, out) || printIf<long>(s, out) || printIf<unsigned long>(s, out) ||
						 printIf<long long>(s, out) || printIf<unsigned long long>(s, out);
	if (!printed) throw std::invalid_argument("unsupported value type");
	return out.str();
}

void requireKnownKeys(const mrpt::containers::yaml& node, const std::set<std::string>& allowed,
					  const std::string& prefix)
{
	if (!node.isMap()) throw std::invalid_argument("expected a map of keys, not a single value or list");
	for (const auto& kv : node.asMap())
	{
		const std::string key = kv.first.isScalar() ? yamlScalarText(kv.first) : "(a map or list)";
		if (allowed.count(key)) continue;
		std::string list;
		for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
		throw std::invalid_argument("unknown key '" + prefix + key + "' (allowed: " + list + ")");
	}
}

namespace
{
[[noreturn]] void notA(const std::string& what, const std::string& text)
{
	throw std::invalid_argument("'" + text + "' is not " + what);
}

}  // namespace

double parseFiniteNumber(const std::string& text)
{
	errno = 0;
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || errno == ERANGE)
		notA("a finite number", text);
	return v;
}

namespace
{
template <typename T>
T parseInteger(const std::string& text)
{
	errno = 0;
	char* end = nullptr;
	const long long v = std::strtoll(text.c_str(), &end, 10);
	if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE) notA("an integer", text);
	if (v < static_cast<long long>(std::numeric_limits<T>::min()) ||
		(v > 0 && static_cast<unsigned long long>(v) > static_cast<unsigned long long>(std::numeric_limits<T>::max())))
		notA("an integer in [" + std::to_string(std::numeric_limits<T>::min()) + ", " +
				 std::to_string(std::numeric_limits<T>::max()) + "]",
			 text);
	return static_cast<T>(v);
}

bool parseBool(const std::string& text)
{
	static const char* yes[] = {"true", "True", "TRUE", "yes", "Yes", "YES", "on", "On", "ON", "1"};
	static const char* no[] = {"false", "False", "FALSE", "no", "No", "NO", "off", "Off", "OFF", "0"};
	for (const char* y : yes)
		if (text == y) return true;
	for (const char* n : no)
		if (text == n) return false;
	notA("true or false", text);
}
}  // namespace

template <typename T>
T yamlScalarAs(const mrpt::containers::yaml& node)
{
	const std::string text = yamlScalarText(node);
	if constexpr (std::is_same_v<T, std::string>) return text;
	else if constexpr (std::is_same_v<T, bool>) return parseBool(text);
	else if constexpr (std::is_floating_point_v<T>)
	{
		const double v = parseFiniteNumber(text);
		if (std::abs(v) > double(std::numeric_limits<T>::max())) notA("a finite number", text);
		return static_cast<T>(v);
	}
	else return parseInteger<T>(text);
}

template std::string yamlScalarAs<std::string>(const mrpt::containers::yaml&);
template bool yamlScalarAs<bool>(const mrpt::containers::yaml&);
template float yamlScalarAs<float>(const mrpt::containers::yaml&);
template double yamlScalarAs<double>(const mrpt::containers::yaml&);
template int yamlScalarAs<int>(const mrpt::containers::yaml&);
template unsigned yamlScalarAs<unsigned>(const mrpt::containers::yaml&);
template long yamlScalarAs<long>(const mrpt::containers::yaml&);
template unsigned long yamlScalarAs<unsigned long>(const mrpt::containers::yaml&);

}  // namespace tagmap
