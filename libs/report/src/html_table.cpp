#include "tagmap/report/html_table.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace tagmap::report
{
namespace
{
// Numbers (and groups of them, "1.0 2.0 3.0") align right, text left.
bool isNumeric(const std::string& s)
{
	return !s.empty() && s.find_first_not_of("0123456789.-+e x") == std::string::npos &&
		   s.find_first_of("0123456789") != std::string::npos;
}
}  // namespace

std::string htmlEscape(const std::string& text)
{
	std::string out;
	out.reserve(text.size());
	for (char ch : text)
		switch (ch)
		{
			case '&': out += "&amp;"; break;
			case '<': out += "&lt;"; break;
			case '>': out += "&gt;"; break;
			case '"': out += "&quot;"; break;
			case '\'': out += "&#39;"; break;
			default: out += ch;
		}
	return out;
}

HtmlTable::HtmlTable(std::vector<std::string> header, std::string cssClass) : class_(std::move(cssClass))
{
	for (const auto& h : header) head_ += "<th>" + htmlEscape(h) + "</th>";
}

void HtmlTable::addRow(const std::vector<std::string>& cells)
{
	body_ += "<tr>";
	for (const auto& c : cells) body_ += (isNumeric(c) ? "<td class=\"num\">" : "<td>") + htmlEscape(c) + "</td>";
	body_ += "</tr>\n";
	rows_++;
}

std::string HtmlTable::html() const
{
	return "<table" + (class_.empty() ? std::string() : " class=\"" + class_ + "\"") + "><thead><tr>" + head_ +
		   "</tr></thead>\n<tbody>\n" + body_ + "</tbody></table>\n";
}

std::string format(const char* fmt, ...)
{
	va_list a, b;
	va_start(a, fmt);
	va_copy(b, a);
	const int n = std::vsnprintf(nullptr, 0, fmt, a);
	va_end(a);
	std::string s(static_cast<size_t>(std::max(n, 0)) + 1, '\0');
	std::vsnprintf(s.data(), s.size(), fmt, b);
	va_end(b);
	s.resize(static_cast<size_t>(std::max(n, 0)));
	return s;
}

}  // namespace tagmap::report
