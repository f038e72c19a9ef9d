// The one exception type for bad input. Its message is the whole one-line
// error a user sees: "<file>: <place>: <what is wrong>".
#pragma once

#include <stdexcept>
#include <string>

namespace tagmap
{
class InputError : public std::runtime_error
{
   public:
	InputError(const std::string& file, const std::string& place, const std::string& what)
		: std::runtime_error(file + ": " + (place.empty() ? "" : place + ": ") + what)
	{
	}
	explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/** One line out of a library's error text. MRPT exceptions carry a banner
 *  and a multi-line call trace; a user needs the line that says what went
 *  wrong (after "Message:"), else the first non-empty line, cut at 200 chars. */
std::string errorSummary(const std::string& text);

}  // namespace tagmap
