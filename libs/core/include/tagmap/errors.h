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

}  // namespace tagmap
