// YAML text to an MRPT tree with syntax errors as one-line InputErrors.
// Shared by every YAML input (scenes, detection configuration), because
// MRPT 2.5.8 alone prints libfyaml's diagnostics over several stderr lines
// and may return a partial tree instead of throwing.
#pragma once

#include <mrpt/containers/yaml.h>

#include <string>

namespace tagmap
{
/** Parses YAML text; syntax errors -> InputError "<file>: not valid YAML:
 *  line L, column C: <reason>". */
mrpt::containers::yaml parseYamlText(const std::string& text, const std::string& file);

/** Reads and parses a YAML file; an unreadable file or bad syntax ->
 *  InputError naming `path`. */
mrpt::containers::yaml readYamlFile(const std::string& path);

}  // namespace tagmap
