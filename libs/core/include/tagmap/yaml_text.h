// YAML text to an MRPT tree with syntax errors as one-line InputErrors.
// Shared by every YAML input (scenes, detection configuration), because
// MRPT 2.5.8 alone prints libfyaml's diagnostics over several stderr lines
// and may return a partial tree instead of throwing.
#pragma once

#include <mrpt/containers/yaml.h>

#include <set>
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

namespace tagmap
{
/** The text of a YAML scalar (whatever type the tree stored it as); a map
 *  or list -> std::invalid_argument. */
std::string yamlScalarText(const mrpt::containers::yaml& node);

/** Every key of the map `node` must be in `allowed`; otherwise
 *  std::invalid_argument "unknown key '<prefix><key>' (allowed: a, b, c)".
 *  The one unknown-key rule of every tagmap YAML input (scenes and detection
 *  configuration): a typo is an error that lists what was meant, never a
 *  silently ignored setting. The caller adds the file and position. */
void requireKnownKeys(const mrpt::containers::yaml& node, const std::set<std::string>& allowed,
					  const std::string& prefix = "");

/** The whole of `text` as a finite double (strtod, nothing left over, no
 *  overflow); otherwise std::invalid_argument "'<text>' is not a finite number". */
double parseFiniteNumber(const std::string& text);

/** A YAML scalar as bool, an integer type, float/double or std::string,
 *  parsed strictly: the whole text must be the value, numbers finite and in
 *  the type's range; otherwise std::invalid_argument saying what is wrong.
 *  Not MRPT's as<T>(): for a number it cannot read (e.g. "1e999") MRPT
 *  2.5.8's yaml.h falls through to an integer path that casts DBL_MAX to
 *  long long, which is undefined behaviour (found by fuzz_config). */
template <typename T>
T yamlScalarAs(const mrpt::containers::yaml& node);

}  // namespace tagmap
