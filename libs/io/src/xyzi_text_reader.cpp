// Plain text "x y z i" per line (.xyzi, .txt, .xyz); blank lines and '#'
// comments (whole-line or trailing) are ignored.
#include "reader_common.h"
#include "readers.h"

namespace tagmap::io::detail
{
void readXyziText(const std::string& path, mrpt::maps::CPointsMapXYZI& out, LoadReport& report)
{
	const FileBytes bytes(path);
	report.format = "xyzi-text";
	report.intensityField = "column 4";
	MapFiller fill(out, report);
	// "0 0 0 0\n" is the shortest record; growing past that estimate is
	// handled by the filler, so this is only a first guess.
	fill.expect(bytes.size() / 32);
	TextLines lines(bytes.data(), bytes.end());
	std::string_view line;
	std::string_view tok[5];
	while (lines.next(line))
	{
		if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
		const size_t n = splitTokens(line, tok, 5);
		if (n == 0) continue;
		if (n == 3)
			throw InputError(path, lineAt(lines.lineNumber()), "3 values (x y z): no intensity column; expected 'x y z i' per line");
		if (n != 4) throw InputError(path, lineAt(lines.lineNumber()), std::to_string(n) + " values, expected 4 ('x y z i')");
		double v[4];
		for (int a = 0; a < 4; ++a)
			if (!parseNumber(tok[a], v[a])) throw InputError(path, lineAt(lines.lineNumber()), quoted(tok[a]) + " is not a number");
		fill.add(v[0], v[1], v[2], static_cast<float>(v[3]));
	}
	fill.finish();
	if (report.pointsRead == 0) throw InputError(path, "", bytes.size() == 0 ? "file is empty" : "no points in the file");
}

}  // namespace tagmap::io::detail
