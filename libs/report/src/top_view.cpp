#include "tagmap/quantile.h"
#include "tagmap/report/top_view.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "tagmap/point_spacing.h"
#include "tagmap/report/intensity_colormap.h"

namespace tagmap::report
{
namespace
{
Eigen::Vector3d pointAt(const mrpt::maps::CPointsMapXYZI& m, size_t i)
{
	return {m.getPointsBufferRef_x()[i], m.getPointsBufferRef_y()[i], m.getPointsBufferRef_z()[i]};
}

// At most ~200 k evenly strided indices: the view's axes and bounds are
// statistics, they do not need every point of a 100 M point map.
std::vector<size_t> sampleIndices(size_t n)
{
	const size_t stride = std::max<size_t>(1, n / 200000);
	std::vector<size_t> idx;
	for (size_t i = 0; i < n; i += stride) idx.push_back(i);
	return idx;
}

ViewFrame chooseAxes(const mrpt::maps::CPointsMapXYZI& map, const std::vector<size_t>& sample,
					 const std::vector<TagDetection>& tags, const TopViewParams& p)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (size_t i : sample) mean += pointAt(map, i);
	mean /= static_cast<double>(sample.size());
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (size_t i : sample)
	{
		const Eigen::Vector3d d = pointAt(map, i) - mean;
		cov += d * d.transpose();
	}
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
	Eigen::Vector3d n = eig.eigenvectors().col(0);  // smallest spread: the plane's normal

	ViewFrame f;
	if (std::abs(n.z()) >= std::cos(p.horizontalToleranceDeg * M_PI / 180)) return f;  // XY, seen from above

	// A wall-like map: look at the side the tags face, else the side the
	// sensor (the map origin) was on; keep z up in the picture.
	double facing = 0;
	for (const auto& t : tags) facing += t.pose.linear().col(2).dot(n);
	if (facing < 0 || (tags.empty() && n.dot(-mean) < 0)) n = -n;
	Eigen::Vector3d v = Eigen::Vector3d::UnitZ() - n.z() * n;
	v.normalize();
	f.n = n;
	f.v = v;
	f.u = v.cross(n);
	return f;
}

double percentile(std::vector<double> v, double pct)
{
	return quantileInPlace(v, pct / 100.0);
}

// Bounds from percentiles, so a few stray far points do not shrink the map
// to a dot; tags are always inside.
void fitBounds(ViewFrame& f, cv::Size& size, const mrpt::maps::CPointsMapXYZI& map, const std::vector<size_t>& sample,
			   const std::vector<TagDetection>& tags, int maxPixels)
{
	std::vector<double> us, vs;
	for (size_t i : sample)
	{
		us.push_back(pointAt(map, i).dot(f.u));
		vs.push_back(pointAt(map, i).dot(f.v));
	}
	double u0 = percentile(us, 0.1), u1 = percentile(us, 99.9), v0 = percentile(vs, 0.1), v1 = percentile(vs, 99.9);
	for (const auto& t : tags)
		for (const auto& c : t.corners)
		{
			u0 = std::min(u0, c.dot(f.u)), u1 = std::max(u1, c.dot(f.u));
			v0 = std::min(v0, c.dot(f.v)), v1 = std::max(v1, c.dot(f.v));
		}
	const double pad = 0.03 * std::max({u1 - u0, v1 - v0, 1e-3});
	u0 -= pad, u1 += pad, v0 -= pad, v1 += pad;
	f.pixel = std::max(u1 - u0, v1 - v0) / maxPixels;
	f.uMin = u0;
	f.vMax = v1;
	size = cv::Size(std::max(1, static_cast<int>(std::ceil((u1 - u0) / f.pixel))),
					std::max(1, static_cast<int>(std::ceil((v1 - v0) / f.pixel))));
}

void fillHoles(cv::Mat& value, cv::Mat& mask, int iterations)
{
	const float lowest = std::numeric_limits<float>::lowest();
	for (int it = 0; it < iterations; it++)
	{
		cv::Mat v = value.clone(), grown, grownMask;
		v.setTo(lowest, mask == 0);
		cv::dilate(v, grown, cv::Mat());
		cv::dilate(mask, grownMask, cv::Mat());
		const cv::Mat holes = (mask == 0) & (grownMask != 0);
		grown.copyTo(value, holes);
		mask = grownMask;
	}
}

// A round length near a sixth of the picture width, drawn bottom-left.
void drawScaleBar(cv::Mat& img, double pixel)
{
	const double want = img.cols * pixel / 6;
	const double base = std::pow(10.0, std::floor(std::log10(want)));
	double len = base;
	for (double m : {2.0, 5.0})
		if (base * m <= want) len = base * m;
	const int px = static_cast<int>(len / pixel), x0 = 16, y0 = img.rows - 16;
	cv::line(img, {x0, y0}, {x0 + px, y0}, cv::Scalar(0, 0, 0), 5);
	cv::line(img, {x0, y0}, {x0 + px, y0}, cv::Scalar(255, 255, 255), 2);
	char text[32];
	std::snprintf(text, sizeof text, len >= 1 ? "%.0f m" : "%.0f cm", len >= 1 ? len : len * 100);
	cv::putText(img, text, {x0, y0 - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
	cv::putText(img, text, {x0, y0 - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
}

void drawTags(cv::Mat& img, const ViewFrame& f, const std::vector<TagDetection>& tags)
{
	const cv::Scalar outline(255, 0, 255), halo(0, 0, 0), text(255, 255, 255);  // magenta: absent from viridis
	const double font = std::clamp(img.cols / 2000.0, 0.45, 0.9);
	for (const auto& t : tags)
	{
		std::vector<cv::Point> poly;
		for (const auto& c : t.corners) poly.push_back(f.toPixel(c));
		const cv::Point centre = f.toPixel(t.position());
		cv::polylines(img, poly, true, outline, 2, cv::LINE_AA);
		cv::circle(img, poly[0], 3, outline, cv::FILLED, cv::LINE_AA);  // vertex 0
		// Small tags on big maps are a few pixels: ring them so they are seen.
		const double edge = cv::norm(poly[0] - poly[2]);
		if (edge < 24) cv::circle(img, centre, 12, outline, 2, cv::LINE_AA);
		const std::string label = tagLabel(t.family, t.id);
		const cv::Point at = centre + cv::Point(static_cast<int>(std::max(14.0, edge / 2)), -6);
		cv::putText(img, label, at, cv::FONT_HERSHEY_SIMPLEX, font, halo, 4, cv::LINE_AA);
		cv::putText(img, label, at, cv::FONT_HERSHEY_SIMPLEX, font, text, 1, cv::LINE_AA);
	}
}
}  // namespace

TopView renderTopView(const mrpt::maps::CPointsMapXYZI& map, const std::vector<TagDetection>& tags,
					  const TopViewParams& p)
{
	TopView out;
	if (map.size() == 0) return out;
	const std::vector<size_t> sample = sampleIndices(map.size());
	ViewFrame& f = out.frame;
	f = chooseAxes(map, sample, tags, p);
	cv::Size size;
	fitBounds(f, size, map, sample, tags, p.maxPixels);

	// Nearest point to the viewer wins each pixel: a roof hides the floor.
	cv::Mat value(size, CV_32F, cv::Scalar(0)), mask(size, CV_8U, cv::Scalar(0));
	cv::Mat depth(size, CV_32F, cv::Scalar(std::numeric_limits<float>::lowest()));
	const float* is = map.getPointsBufferRef_intensity().data();
	for (size_t i = 0; i < map.size(); i++)
	{
		const Eigen::Vector3d q = pointAt(map, i);
		const cv::Point2d px = f.toPixel(q);
		const int c = static_cast<int>(px.x), r = static_cast<int>(px.y);
		if (px.x < 0 || px.y < 0 || c >= size.width || r >= size.height || !std::isfinite(is[i])) continue;
		const float d = static_cast<float>(q.dot(f.n));
		if (d <= depth.at<float>(r, c)) continue;
		depth.at<float>(r, c) = d;
		value.at<float>(r, c) = is[i];
		mask.at<uint8_t>(r, c) = 255;
	}
	const double spacing = estimatePointSpacing(map.getPointsBufferRef_x().data(), map.getPointsBufferRef_y().data(),
												map.getPointsBufferRef_z().data(), map.size());
	fillHoles(value, mask, std::clamp(static_cast<int>(std::ceil(0.5 * spacing / f.pixel)), 1, p.maxFillIterations));
	const IntensityRange range = percentileRange(is, map.size(), p.loPercent, p.hiPercent);
	out.image = colorize(value, mask, range, p.colormap, cv::Scalar(40, 40, 40));
	drawTags(out.image, f, tags);
	drawScaleBar(out.image, f.pixel);

	char cap[200];
	const bool xy = f.n.isApprox(Eigen::Vector3d::UnitZ());
	std::snprintf(cap, sizeof cap, "%s, %.1f cm per pixel, intensity %.3g..%.3g (%g-%g percentiles)",
				  xy ? "Top view (XY plane, seen from +z)" : "View onto the map's dominant plane (z up)", f.pixel * 100,
				  range.lo, range.hi, p.loPercent, p.hiPercent);
	out.caption = cap;
	return out;
}

}  // namespace tagmap::report
