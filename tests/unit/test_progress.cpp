#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "tagmap/report/progress_printer.h"

using tagmap::report::ProgressParams;
using tagmap::report::ProgressPrinter;

namespace
{
// Runs a short fake detection through a printer of `style`, returns its output.
std::string printed(ProgressParams::Style style)
{
	std::FILE* f = std::tmpfile();
	{
		ProgressParams p;
		p.style = style;
		p.stream = f;
		ProgressPrinter progress(p);
		progress.update("reading", 0, 0);
		progress.update("reading", 1500, 1500);
		auto cb = progress.callback();
		cb("clustering", 0, 1);
		cb("clustering", 1, 1);
		cb("decode", 0, 3);
		cb("decode", 1, 3);
		cb("decode", 2, 3);  // ends short, like a candidate with no plane: the next stage ends it
		progress.update("report", 0, 0);
		progress.finish();
	}
	std::string s;
	std::rewind(f);
	for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
	std::fclose(f);
	return s;
}
}  // namespace

TEST(Progress, LinesSayWhenEachStageEnds)
{
	const std::string s = printed(ProgressParams::Style::Lines);
	EXPECT_NE(s.find("reading              done 1,500\n"), std::string::npos) << s;
	EXPECT_NE(s.find("clustering           done"), std::string::npos) << s;
	EXPECT_NE(s.find("decode               done 2/3"), std::string::npos) << s;
	EXPECT_NE(s.find("report               done"), std::string::npos) << s;
	EXPECT_EQ(s.find('\r'), std::string::npos) << "no terminal control codes in logs";
}

TEST(Progress, BarRedrawsInPlace)
{
	const std::string s = printed(ProgressParams::Style::Bar);
	EXPECT_NE(s.find("\r\033[K"), std::string::npos);
	EXPECT_NE(s.find("0/3"), std::string::npos) << s;  // a stage is drawn when it starts
	// Updates faster than redrawSeconds are not drawn: the ticker draws them.
	EXPECT_EQ(s.find("1/3"), std::string::npos) << s;
	EXPECT_EQ(s.back(), '\n');
}

TEST(Progress, QuietPrintsNothing) { EXPECT_EQ(printed(ProgressParams::Style::Quiet), ""); }
