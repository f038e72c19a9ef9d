#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>

#include "../report/fixture_map.h"
#include "tagmap/errors.h"
#include "tagmap/report/html_table.h"
#include "tagmap/report/report_writer.h"
#include "tagmap/report/top_view.h"

namespace fs = std::filesystem;
using namespace tagmap;

namespace
{
struct Run
{
	mrpt::maps::CPointsMapXYZI map = tagmap::testing::makeReportFixtureMap();
	PipelineParams params;
	Detections found = Pipeline(params).detect(map, {}, true);
};

const Run& run()
{
	static const Run r;
	return r;
}

std::string readText(const fs::path& p)
{
	std::ifstream in(p);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

fs::path freshDir(const std::string& name)
{
	const fs::path d = fs::path(::testing::TempDir()) / name;
	fs::remove_all(d);
	return d;
}

size_t count(const std::string& text, const std::string& what)
{
	size_t n = 0;
	for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) n++;
	return n;
}
}  // namespace

TEST(Report, WritesPageWithEveryImage)
{
	ASSERT_EQ(run().found.tags.size(), 2u);
	const fs::path dir = freshDir("tagmap_report_page");
	report::writeReport(dir.string(), {"walls.pcd", "synthetic", "tagmap detect walls.pcd", run().map, run().found,
									   run().params});
	const std::string html = readText(dir / "index.html");
	EXPECT_NE(html.find("tag36h11"), std::string::npos);
	EXPECT_NE(html.find("aruco_6x6_50"), std::string::npos);  // the smallest dictionary holding the id
	EXPECT_NE(html.find("id=\"image-check\""), std::string::npos);

	// Every <img> names a PNG that exists and decodes.
	const std::regex img("<img [^>]*src=\"([^\"]+)\"");
	size_t images = 0;
	for (std::sregex_iterator it(html.begin(), html.end(), img), end; it != end; ++it, images++)
		EXPECT_FALSE(cv::imread((dir / (*it)[1].str()).string()).empty()) << (*it)[1];
	size_t withImage = 0;
	for (const auto& c : run().found.candidates) withImage += !c.image.empty();
	EXPECT_EQ(images, 1 + withImage);
	EXPECT_GE(count(html, "decoded tag36h11:7"), 1u);

	// Nothing left beside it.
	for (const auto& e : fs::directory_iterator(dir.parent_path()))
		EXPECT_EQ(e.path().filename().string().find("tagmap_report_page."), std::string::npos) << e.path();
}

TEST(Report, ReplacesItsOwnFolderButNoOtherOne)
{
	const fs::path dir = freshDir("tagmap_report_replace");
	const report::ReportInput in{"walls.pcd", "", "", run().map, run().found, run().params};
	report::writeReport(dir.string(), in);
	std::ofstream(dir / "stale.png") << "x";
	report::writeReport(dir.string(), in);  // a second run replaces the first one whole
	EXPECT_FALSE(fs::exists(dir / "stale.png"));
	EXPECT_TRUE(fs::exists(dir / "index.html"));

	const fs::path precious = freshDir("tagmap_report_precious");
	fs::create_directories(precious);
	std::ofstream(precious / "thesis.tex") << "years of work";
	EXPECT_THROW(report::writeReport(precious.string(), in), InputError);
	EXPECT_EQ(readText(precious / "thesis.tex"), "years of work");

	const fs::path file = fs::path(::testing::TempDir()) / "tagmap_report_file";
	std::ofstream(file) << "x";
	EXPECT_THROW(report::checkReportDir(file.string()), InputError);
}

TEST(Report, TopViewOutlinesTags)
{
	const report::TopView v = report::renderTopView(run().map, run().found.tags);
	ASSERT_FALSE(v.image.empty());
	EXPECT_LE(std::max(v.image.cols, v.image.rows), report::TopViewParams{}.maxPixels);
	// The walls face -y: seen from the front, z up, x to the right.
	EXPECT_GT(v.frame.v.z(), 0.99);
	EXPECT_LT(v.frame.n.y(), -0.99);
	cv::Mat m;
	cv::inRange(v.image, cv::Scalar(250, 0, 250), cv::Scalar(255, 5, 255), m);
	EXPECT_GT(cv::countNonZero(m), 100);
}

TEST(Report, HtmlEscape)
{
	EXPECT_EQ(report::htmlEscape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

TEST(Report, ARejectedCandidateListsEachReadAndWhyItFailed)
{
	// The candidate's verdict is its last read's; a user looking for a
	// missed tag needs every read's.
	Detections found = run().found;
	CandidateReport c;
	c.image = cv::Mat(64, 64, CV_8U, cv::Scalar(128));
	c.verdict = Verdict::ByChance;
	DecodedTag2D a, b;
	a.family = "tag36h11", a.id = 422;
	b.family = "aruco_6x6_1000", b.id = 623;
	for (DecodedTag2D* d : {&a, &b})
		d->corners = {Eigen::Vector2d(16, 16), Eigen::Vector2d(48, 16), Eigen::Vector2d(48, 48), Eigen::Vector2d(16, 48)};
	c.decoded = {a, b};
	c.readVerdicts = {Verdict::CodeNotInPoints, Verdict::ByChance};
	found.candidates.push_back(c);
	const fs::path dir = freshDir("tagmap_report_reads");
	report::writeReport(dir.string(), {"walls.pcd", "synthetic", "tagmap detect walls.pcd", run().map, found,
									   run().params});
	EXPECT_EQ(count(readText(dir / "index.html"),
					"by_chance (read tag36h11:422 code_not_in_points, aruco_6x6_1000:623 by_chance)"),
			  1u);
}

// The report page of the synthetic walls with one more candidate without
// an image (a copy of the first one, changed by `change`).
template <typename F>
std::string pageWithOneMoreCandidate(const char* dirName, F change)
{
	Detections found = run().found;
	if (found.candidates.empty()) return {};
	CandidateReport c = found.candidates.front();
	c.image = cv::Mat();
	c.sameBoxAs.reset();
	c.onTagOf.reset();
	change(c);
	found.candidates.push_back(c);
	const fs::path dir = freshDir(dirName);
	report::writeReport(dir.string(), {"walls.pcd", "synthetic", "tagmap detect walls.pcd", run().map, found,
									   run().params});
	return readText(dir / "index.html");
}

TEST(Report, ACandidateWithAnEarlierOnesBoxNamesIt)
{
	const std::string page = pageWithOneMoreCandidate("tagmap_report_same_box", [](CandidateReport& c) {
		c.verdict = Verdict::SameBox;
		c.sameBoxAs = 0;
	});
	EXPECT_EQ(count(page, "same_box as #0<"), 1u);
}

TEST(Report, ACandidateCentredOnADecodedTagNamesTheOneThatDecodedIt)
{
	const std::string page = pageWithOneMoreCandidate("tagmap_report_on_decoded_tag", [](CandidateReport& c) {
		c.verdict = Verdict::OnDecodedTag;
		c.onTagOf = 9999;  // an index no real candidate of this map names
	});
	EXPECT_EQ(count(page, "on_decoded_tag of #9999<"), 1u);
}
