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
/** Offset of the first byte that is not part of valid UTF-8, or npos. */
size_t firstInvalidUtf8(const std::string& text)
{
	const auto* p = reinterpret_cast<const unsigned char*>(text.data());
	const size_t n = text.size();
	for (size_t i = 0; i < n;)
	{
		const unsigned c = p[i];
		const size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
		if (len == 0 || (len == 2 && c < 0xc2) || len > n - i) return i;
		for (size_t k = 1; k < len; k++)
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
