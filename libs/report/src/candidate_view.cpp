#include "tagmap/report/candidate_view.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace tagmap::report
{
namespace
{
void outlinedText(cv::Mat& img, const std::string& s, cv::Point at, double scale, const cv::Scalar& colour)
{
	cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 4, cv::LINE_AA);
	cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}
}  // namespace

cv::Mat renderCandidateView(const CandidateReport& c, const CandidateViewParams& p)
{
	if (c.image.empty()) return {};
	const int edge = std::max(c.image.cols, c.image.rows);
	double scale = 1;
	if (edge < p.minEdge) scale = std::ceil(static_cast<double>(p.minEdge) / edge);
	if (edge > p.maxEdge) scale = static_cast<double>(p.maxEdge) / edge;
	cv::Mat gray, img;
	cv::resize(c.image, gray, cv::Size(), scale, scale, scale >= 1 ? cv::INTER_NEAREST : cv::INTER_AREA);
	cv::cvtColor(gray, img, cv::COLOR_GRAY2BGR);

	const cv::Scalar accepted(60, 200, 60), rejected(0, 140, 255);
	for (const DecodedTag2D& d : c.decoded)
	{
		const std::string label = tagLabel(d.family, d.id);
		const bool ok = std::find(c.decodedLabels.begin(), c.decodedLabels.end(), label) != c.decodedLabels.end();
		const cv::Scalar colour = ok ? accepted : rejected;
		std::vector<cv::Point> quad;
		cv::Point2d centre(0, 0);
		for (const auto& q : d.corners)
		{
			// Corner coordinates are continuous: pixel (c, r) covers [c, c+1).
			quad.emplace_back(cv::Point2d(q.x() * scale, q.y() * scale));
			centre += 0.25 * cv::Point2d(q.x() * scale, q.y() * scale);
		}
		cv::polylines(img, quad, true, colour, 2, cv::LINE_AA);
		for (int k = 0; k < 4; k++)
		{
			cv::circle(img, quad[static_cast<size_t>(k)], 4, colour, cv::FILLED, cv::LINE_AA);
			// Index label pushed outwards from the centre, so it sits off the quad.
			const cv::Point2d out = cv::Point2d(quad[static_cast<size_t>(k)]) - centre;
			const cv::Point2d at = cv::Point2d(quad[static_cast<size_t>(k)]) + out * (14.0 / std::max(1.0, cv::norm(out)));
			outlinedText(img, std::to_string(k), cv::Point(at) + cv::Point(-5, 5), 0.6, colour);
		}
		outlinedText(img, label + (d.mirrored ? " (mirrored)" : ""), cv::Point(centre) + cv::Point(-40, 5), 0.5,
					 cv::Scalar(255, 255, 255));
	}
	outlinedText(img, verdictName(c.verdict), cv::Point(6, 18), 0.55, c.verdict == Verdict::Decoded ? accepted : rejected);
	return img;
}

}  // namespace tagmap::report
