#include "tagmap/report/report_writer.h"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "tagmap/errors.h"
#include "tagmap/report/atomic_directory.h"
#include "tagmap/report/html_table.h"
#include "tagmap/report/report_page.h"

namespace tagmap::report
{
namespace
{
const char* kMarker = ".tagmap-report";

void savePng(const std::string& path, const cv::Mat& img)
{
	if (!cv::imwrite(path, img)) throw InputError(path, "", "cannot write PNG image");
}

// Decoded first (what people look for), then the rejections that got as far
// as an image, biggest cluster first within each.
std::vector<size_t> galleryOrder(const Detections& found)
{
	std::vector<size_t> idx;
	for (size_t i = 0; i < found.candidates.size(); i++)
		if (!found.candidates[i].image.empty()) idx.push_back(i);
	auto rank = [&](size_t i) { return found.candidates[i].verdict == Verdict::Decoded ? 0 : 1; };
	std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
		if (rank(a) != rank(b)) return rank(a) < rank(b);
		return found.candidates[a].clusterPoints > found.candidates[b].clusterPoints;
	});
	return idx;
}
}  // namespace

void checkReportDir(const std::string& dir) { checkDirectoryReplaceable(dir, kMarker); }

void writeReport(const std::string& dir, const ReportInput& in, const ReportParams& p)
{
	writeDirectoryAtomically(dir, kMarker, [&](const std::string& tmp) {
		PageImages images;
		const TopView top = renderTopView(in.map, in.found.tags, p.topView);
		if (!top.image.empty())
		{
			savePng(tmp + "/map.png", top.image);
			images.topView = "map.png";
			images.topViewCaption = top.caption;
		}
		std::vector<size_t> order = galleryOrder(in.found);
		images.candidatesOmitted = order.size() > p.maxCandidateImages ? order.size() - p.maxCandidateImages : 0;
		order.resize(order.size() - images.candidatesOmitted);
		if (!order.empty()) std::filesystem::create_directory(tmp + "/candidates");
		for (size_t i : order)
		{
			const std::string rel = format("candidates/c%05zu.png", i);
			savePng(tmp + "/" + rel, renderCandidateView(in.found.candidates[i], p.candidate));
			images.candidates.push_back({i, rel});
		}
		std::ofstream html(tmp + "/index.html", std::ios::binary);
		html << reportPage(in, images, p);
		html.close();
		if (!html) throw InputError(dir + "/index.html", "", "write failed (disk full?)");
	});
}

}  // namespace tagmap::report
