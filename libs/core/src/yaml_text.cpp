#include "tagmap/yaml_text.h"

#include <unistd.h>

#include <algorithm>
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
}  // namespace

mrpt::containers::yaml parseYamlText(const std::string& text, const std::string& file)
{
	checkUtf8(text, file);
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

}  // namespace tagmap
