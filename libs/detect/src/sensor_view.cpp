#include "tagmap/sensor_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "tagmap/fast_atan2.h"
#include "tagmap/intermediate_plane.h"
#include "tagmap/point_stats.h"
#include "tagmap/tag_family.h"

namespace tagmap
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr int kPadding = 8;  // pixels around the scan, so a tag at its edge still decodes

// Where the image's azimuth starts: the middle of the widest azimuth gap
// (a 70 deg Livox frame: the other 290 deg), or anywhere on a full circle,
// which is then repeated `overlap` past the seam.
struct Seam
{
	double at = kPi;  // azimuths are taken in (at - 2 pi, at]
	bool fullCircle = true;
};

Seam findSeam(const std::vector<Eigen::Vector2d>& ae, double overlap)
{
	constexpr int kBins = 360;
	std::vector<char> used(kBins, 0);
	for (const Eigen::Vector2d& a : ae)
		used[std::clamp(static_cast<int>((a.x() + kPi) / (2 * kPi) * kBins), 0, kBins - 1)] = 1;
	int bestStart = -1, bestLength = 0;
	for (int s = 0; s < kBins; s++)
	{
		if (used[s] || used[(s + kBins - 1) % kBins]) continue;	// runs start after a used bin
		int len = 0;
		while (len < kBins && !used[(s + len) % kBins]) len++;
		if (len > bestLength) bestLength = len, bestStart = s;
	}
	Seam seam;
	if (bestStart >= 0 && bestLength * 2 * kPi / kBins > 2 * overlap)
	{
		seam.at = -kPi + (bestStart + 0.5 * bestLength) * 2 * kPi / kBins;
		seam.fullCircle = false;
	}
	return seam;
}

double unwrapBelow(double a, double seam)
{
	while (a > seam) a -= 2 * kPi;
	while (a <= seam - 2 * kPi) a += 2 * kPi;
	return a;
}

// sqrt of the solid angle (in azimuth x elevation units, as the image is)
// the scan covers per point: occupied cells of a grid twice as coarse as
// the spacing the points' bounding rectangle would give.
double angularSpacing(const std::vector<Eigen::Vector2d>& ae, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi)
{
	const double n = static_cast<double>(ae.size());
	const double cell = 2 * std::sqrt(std::max((hi - lo).prod(), 1e-12) / n);
	const int W = static_cast<int>((hi.x() - lo.x()) / cell) + 1, H = static_cast<int>((hi.y() - lo.y()) / cell) + 1;
	std::vector<char> used(static_cast<size_t>(W) * H, 0);
	for (const Eigen::Vector2d& p : ae)
		used[static_cast<size_t>((p.y() - lo.y()) / cell) * W + static_cast<size_t>((p.x() - lo.x()) / cell)] = 1;
	const double occupied = static_cast<double>(std::count(used.begin(), used.end(), 1));
	return std::sqrt(occupied * cell * cell / n);
}

// Where a point of `view` shows: its own image position and, for a 360 deg
// scan repeated past its seam, that position a full turn to the left (the
// render splats both). Only for placed points (pixelOf x >= 0).
std::array<Eigen::Vector2d, 2> imagePositions(const SensorView& view, const Eigen::Vector2f& f)
{
	const double turn = 2 * kPi / view.pixel;
	return {Eigen::Vector2d(f.x(), f.y()), Eigen::Vector2d(f.x() - turn, f.y())};
}

bool insideQuad(const std::array<Eigen::Vector2d, 4>& q, const Eigen::Vector2d& p)
{
	int sign = 0;
	for (int k = 0; k < 4; k++)
	{
		const Eigen::Vector2d e = q[(k + 1) % 4] - q[k], d = p - q[k];
		const double c = e.x() * d.y() - e.y() * d.x();
		const int s = c > 0 ? 1 : (c < 0 ? -1 : 0);
		if (s == 0) continue;
		if (sign == 0) sign = s;
		else if (s != sign) return false;
	}
	return true;
}
}  // namespace

Eigen::Vector3d SensorView::ray(const Eigen::Vector2d& xy) const
{
	const double az = azimuthLeft - xy.x() * pixel, el = elevationTop - xy.y() * pixel;
	return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

SensorView renderSensorView(const float* xs, const float* ys, const float* zs, const float* is, size_t n,
							const SensorViewParams& p)
{
	SensorView view;
	view.pixelOf.assign(n, Eigen::Vector2f(-1, -1));
	// Each valid point's (azimuth, elevation); the azimuth is unwrapped
	// below the seam once the seam is known.
	std::vector<uint32_t> valid;
	std::vector<Eigen::Vector2d> ae;
	valid.reserve(n);
	ae.reserve(n);
	for (size_t i = 0; i < n; i++)
	{
		// hypotf's own arithmetic (the float inputs' squares summed in
		// double, the root rounded to float), without its call.
		const double h = static_cast<float>(std::sqrt(static_cast<double>(xs[i]) * xs[i] + static_cast<double>(ys[i]) * ys[i]));
		if (!(h > 0 || zs[i] != 0) || !std::isfinite(h) || !std::isfinite(zs[i]) || !std::isfinite(is[i])) continue;
		valid.push_back(static_cast<uint32_t>(i));
		ae.emplace_back(fastAtan2(ys[i], xs[i]), fastAtan2(zs[i], h));
	}
	if (valid.size() < 16) return view;
	const double overlap = p.seamOverlapDeg * kPi / 180;
	const Seam seam = findSeam(ae, overlap);
	// The bounds in scalars: a vector min read back right after the
	// azimuth's store waits for it (store forwarding; a tenth of the render).
	double loAz = 1e300, loEl = 1e300, hiAz = -1e300, hiEl = -1e300;
	for (Eigen::Vector2d& a : ae)
	{
		const double az = unwrapBelow(a.x(), seam.at), el = a.y();
		a.x() = az;
		loAz = std::min(loAz, az), hiAz = std::max(hiAz, az);
		loEl = std::min(loEl, el), hiEl = std::max(hiEl, el);
	}
	const Eigen::Vector2d lo(loAz, loEl), hi(hiAz, hiEl);
	view.angularSpacing = angularSpacing(ae, lo, hi);
	const double left = seam.fullCircle ? seam.at + overlap : hi.x();
	view.pixel = std::max({p.pixelSpacings * view.angularSpacing, (left - lo.x()) / p.maxImagePixels,
						   (hi.y() - lo.y()) / p.maxImagePixels});
	view.azimuthLeft = left + kPadding * view.pixel;
	view.elevationTop = hi.y() + kPadding * view.pixel;
	const int W = static_cast<int>(std::ceil((view.azimuthLeft - lo.x()) / view.pixel)) + kPadding;
	const int H = static_cast<int>(std::ceil((view.elevationTop - lo.y()) / view.pixel)) + kPadding;

	// Normalised convolution, as on the intermediate plane: each point's
	// intensity split bilinearly over its 4 pixels, then both sums blurred
	// by the splat's Gaussian.
	cv::Mat wsum(H, W, CV_32F, cv::Scalar(0)), isum(H, W, CV_32F, cv::Scalar(0));
	auto splat = [&](double x, double y, float I) {
		const int cx = static_cast<int>(std::floor(x - 0.5)), cy = static_cast<int>(std::floor(y - 0.5));
		const float fx = static_cast<float>(x - 0.5 - cx), fy = static_cast<float>(y - 0.5 - cy);
		const float wx[2] = {1 - fx, fx}, wy[2] = {1 - fy, fy};
		for (int dy = 0; dy <= 1; dy++)
		{
			const int py = cy + dy;
			if (py < 0 || py >= H) continue;
			float* wrow = wsum.ptr<float>(py);
			float* irow = isum.ptr<float>(py);
			for (int dx = 0; dx <= 1; dx++)
			{
				const int px = cx + dx;
				if (px < 0 || px >= W) continue;
				const float w = wx[dx] * wy[dy];
				wrow[px] += w;
				irow[px] += w * I;
			}
		}
	};
	const double wrapColumns = 2 * kPi / view.pixel;
	std::vector<float> vals;
	vals.reserve(valid.size());
	for (size_t k = 0; k < valid.size(); k++)
	{
		const uint32_t i = valid[k];
		const double x = (view.azimuthLeft - ae[k].x()) / view.pixel, y = (view.elevationTop - ae[k].y()) / view.pixel;
		view.pixelOf[i] = Eigen::Vector2f(static_cast<float>(x), static_cast<float>(y));
		splat(x, y, is[i]);
		// Repeated past the seam: at the image's left, a full turn on.
		if (seam.fullCircle && x - wrapColumns >= 0) splat(x - wrapColumns, y, is[i]);
		vals.push_back(is[i]);
	}
	const double sigma = std::max(0.5, p.splatSpacings * view.angularSpacing / view.pixel);
	cv::Mat bw, bi;
	cv::GaussianBlur(wsum, bw, cv::Size(), sigma);
	cv::GaussianBlur(isum, bi, cv::Size(), sigma);
	cv::Mat img, known;
	// Known where a point's splat is at least 5 % of its peak (the
	// intermediate plane's rule); holes (between scan lines, a tag's part
	// outside the field of view) are filled from blurrier versions up to
	// `fillSpacings`, the rest (sky, beyond range) stays grey.
	const float peak = static_cast<float>(1 / (2 * kPi * sigma * sigma));
	normalisedMean(bw, bi, 1e-9f, 0.05f * peak, img, known);
	fillHoles(wsum, isum, 2 * sigma, p.fillSpacings * view.angularSpacing / view.pixel, img, known);
	view.gray = contrastNormalised(img, std::move(vals), known);
	return view;
}

bool boxOfRead(const SensorView& view, const DecodedTag2D& read, const float* xs, const float* ys, const float* zs,
			   const std::vector<uint32_t>& points, double band, OrientedBox& box,
			   std::array<Eigen::Vector3d, 4>* cornersOut)
{
	if (view.gray.empty()) return false;
	// The points inside the quad shrunk by 10 % towards its centre: the
	// border's outer edge may catch the background behind the tag.
	Eigen::Vector2d mid = Eigen::Vector2d::Zero();
	for (const auto& c : read.corners) mid += c / 4;
	std::array<Eigen::Vector2d, 4> inner;
	Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
	for (int k = 0; k < 4; k++)
	{
		inner[k] = mid + 0.9 * (read.corners[k] - mid);
		lo = lo.cwiseMin(inner[k]);
		hi = hi.cwiseMax(inner[k]);
	}
	std::vector<uint32_t> inside;
	for (const uint32_t i : points)
	{
		if (view.pixelOf[i].x() < 0) continue;  // not placed in the view
		for (const Eigen::Vector2d& xy : imagePositions(view, view.pixelOf[i]))
		{
			if (xy.x() < lo.x() || xy.x() > hi.x() || xy.y() < lo.y() || xy.y() > hi.y()) continue;
			if (insideQuad(inner, xy)) inside.push_back(i);
		}
	}
	// A plane through them, refitted without the points beyond 3 RMS.
	PlaneFit fit;
	std::vector<uint32_t> in = inside;
	for (int iter = 0; iter < 3 && in.size() >= 8; iter++)
	{
		fit = fitPlane(xs, ys, zs, in);
		in.clear();
		for (uint32_t i : inside)
			if (std::abs((Eigen::Vector3d(xs[i], ys[i], zs[i]) - fit.centroid).dot(fit.normal)) <= 3 * fit.rms + 1e-9)
				in.push_back(i);
	}
	if (in.size() < 8) return false;
	const Eigen::Vector3d c = fit.centroid;
	const double rms = fit.rms;
	Eigen::Vector3d normal = fit.normal;
	if (normal.dot(c) > 0) normal = -normal;  // towards the sensor
	std::array<Eigen::Vector3d, 4> corners;
	for (int k = 0; k < 4; k++)
	{
		const Eigen::Vector3d d = view.ray(read.corners[k]);
		const double cosine = normal.dot(d);
		if (std::abs(cosine) < 0.05) return false;  // grazing: the corner is nowhere on the plane
		const double t = normal.dot(c) / cosine;
		if (!(t > 0)) return false;
		corners[k] = t * d;
	}
	const Eigen::Vector3d across = (corners[1] - corners[0]) + (corners[2] - corners[3]);
	const Eigen::Vector3d down = (corners[3] - corners[0]) + (corners[2] - corners[1]);
	Eigen::Vector3d u = across - normal * normal.dot(across);
	if (!(u.norm() > 0)) return false;
	u.normalize();
	box.axes.col(0) = u;
	box.axes.col(1) = normal.cross(u);
	box.axes.col(2) = u.cross(box.axes.col(1));
	box.center = (corners[0] + corners[1] + corners[2] + corners[3]) / 4;
	box.thickness = 4 * rms;
	// The read's quad is the border square; the printed tag reaches a cell
	// further (the quiet zone), as far as the edge points of a map path
	// cluster do.
	const int cells = findFamily(read.family)->borderCells;
	const double grow = cells > 0 ? (cells + 2.0) / cells : 1.0;
	box.extent = Eigen::Vector3d(grow * 0.5 * across.norm() + 2 * band, grow * 0.5 * std::abs(down.dot(box.axes.col(1))) + 2 * band,
								 box.thickness);
	if (cornersOut) *cornersOut = corners;
	return true;
}

std::vector<uint32_t> pointsNearReads(const SensorView& view, const std::vector<DecodedTag2D>& reads, double sides)
{
	std::vector<Eigen::AlignedBox2d> rects;
	for (const DecodedTag2D& d : reads)
	{
		Eigen::AlignedBox2d r;
		for (const auto& c : d.corners) r.extend(c);
		const double grow = sides * r.sizes().maxCoeff();
		rects.emplace_back(r.min() - Eigen::Vector2d::Constant(grow), r.max() + Eigen::Vector2d::Constant(grow));
	}
	std::vector<uint32_t> near;
	for (size_t i = 0; i < view.pixelOf.size(); i++)
	{
		if (view.pixelOf[i].x() < 0) continue;  // not placed in the view
		const std::array<Eigen::Vector2d, 2> xy = imagePositions(view, view.pixelOf[i]);
		if (std::any_of(rects.begin(), rects.end(),
						[&](const Eigen::AlignedBox2d& r) { return r.contains(xy[0]) || r.contains(xy[1]); }))
			near.push_back(static_cast<uint32_t>(i));
	}
	return near;
}

}  // namespace tagmap
