// The little HTML the report needs: escaping and tables. Cells are text and
// are always escaped, so file names and family strings cannot break the page.
#pragma once

#include <string>
#include <vector>

namespace tagmap::report
{
std::string htmlEscape(const std::string& text);

class HtmlTable
{
   public:
	explicit HtmlTable(std::vector<std::string> header, std::string cssClass = {});
	void addRow(const std::vector<std::string>& cells);
	size_t rows() const { return rows_; }
	std::string html() const;

   private:
	std::string head_, body_, class_;
	size_t rows_ = 0;
};

/** printf into a std::string (numbers in tables and captions). */
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace tagmap::report
