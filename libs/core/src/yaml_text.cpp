#include "tagmap/yaml_text.h"

#include <unistd.h>

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
mrpt::containers::yaml parseYamlText(const std::string& text, const std::string& file)
{
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
