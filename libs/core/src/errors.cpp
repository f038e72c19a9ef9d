#include "tagmap/errors.h"

#include <string_view>

namespace tagmap
{
std::string errorSummary(const std::string& text)
{
	std::string_view s(text);
	if (const size_t m = s.find("Message:"); m != std::string_view::npos) s.remove_prefix(m + 8);
	while (!s.empty())
	{
		const size_t nl = s.find('\n');
		std::string_view line = s.substr(0, nl);
		while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
		while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.remove_suffix(1);
		if (!line.empty() && line.find_first_not_of('=') != std::string_view::npos) return std::string(line.substr(0, 200));
		if (nl == std::string_view::npos) break;
		s.remove_prefix(nl + 1);
	}
	return "unknown error";
}

}  // namespace tagmap
