#include "tagmap/tag_quads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

namespace tagmap
{
namespace
{
// An 8-bit image as the bilinear sampler reads it: rows, and the last
// position with a pixel to its right and below, taken once per image (the
// border-square search samples ~18 000 times per square it fits).
struct GrayPixels
{
	explicit GrayPixels(const cv::Mat& img)
		: data(img.data), step(img.step[0]), lastX(img.cols - 1), lastY(img.rows - 1)
	{
	}
	const uint8_t* data;
	size_t step;
	double lastX, lastY;
};

// Grey levels as doubles: a table lookup is cheaper than the conversion,
// and the values are the same.
const std::array<double, 256> kGrayLevels = [] {
	std::array<double, 256> v{};
	for (int i = 0; i < 256; i++) v[static_cast<size_t>(i)] = i;
	return v;
}();

double sampleBilinear(const GrayPixels& img, double x, double y)
{
	// Image coordinates with pixel centres on half-integers.
	x -= 0.5;
	y -= 0.5;
	if (x < 0 || y < 0 || x >= img.lastX || y >= img.lastY) return -1;
	const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
	const double fx = x - x0, fy = y - y0;
	const uint8_t* a = img.data + img.step * static_cast<size_t>(y0);
	const uint8_t* b = a + img.step;
	const std::array<double, 256>& g = kGrayLevels;
	return (1 - fy) * ((1 - fx) * g[a[x0]] + fx * g[a[x0 + 1]]) + fy * ((1 - fx) * g[b[x0]] + fx * g[b[x0 + 1]]);
}

/** Mean of the image along a square's outline just outside minus just
 *  inside it: a tag's border square is dark inside a light quiet zone. */
double borderContrast(const GrayPixels& img, double cx, double cy, double half, double angle)
{
	const double d = 0.12 * half;  // about half a cell
	// The sides' outward normals: the first one turned by quarter turns
	// (one sine and cosine per square; the search evaluates ~90 squares).
	const double c = std::cos(angle), s = std::sin(angle);
	const double normals[4][2] = {{c, s}, {-s, c}, {-c, -s}, {s, -c}};
	// Where along a side the samples lie, the same for every side.
	std::array<double, 13> along;
	for (int k = -6; k <= 6; k++) along[static_cast<size_t>(k + 6)] = half * 0.85 * k / 6.0;
	double sum = 0;
	int n = 0;
	for (const auto& normal : normals)
	{
		// Outward normal of this side, and the direction along it.
		const double nx = normal[0], ny = normal[1], tx = -ny, ty = nx;
		const double midX = cx + nx * half, midY = cy + ny * half, offX = nx * d, offY = ny * d;
		for (const double t : along)
		{
			const double px = midX + tx * t, py = midY + ty * t;
			const double out = sampleBilinear(img, px + offX, py + offY);
			const double in = sampleBilinear(img, px - offX, py - offY);
			if (out < 0 || in < 0) continue;
			sum += out - in;
			n++;
		}
	}
	return n > 20 ? sum / n : -1e9;
}

/** On `smooth` (the image blurred at sigma 1, once per image): the square
 *  (centre, half side, angle) with the strongest dark-inside
 *  contrast along its outline, by coordinate search from `seed` with
 *  shrinking steps. Blur moves a border's thresholded outline but not the
 *  place where light turns dark fastest. */
std::vector<cv::Point2f> fitBorderSquare(const cv::Mat& smoothImage, const cv::RotatedRect& seed)
{
	const GrayPixels smooth(smoothImage);
	double x[4] = {seed.center.x + 0.5, seed.center.y + 0.5, 0.25 * (seed.size.width + seed.size.height),
				   seed.angle * M_PI / 180};
	double best = borderContrast(smooth, x[0], x[1], x[2], x[3]);
	// A point met again (bit for bit) cannot win: its contrast was at most
	// the best when it was met, and the best only grows.
	std::vector<std::array<double, 4>> met = {{x[0], x[1], x[2], x[3]}};
	for (double step = 0.1; step > 0.01; step *= 0.5)
	{
		const double steps[4] = {step * x[2], step * x[2], 0.5 * step * x[2], 0.5 * step};
		for (bool improved = true; improved;)
		{
			improved = false;
			for (int j = 0; j < 4; j++)
				for (double sign : {-1.0, 1.0})
				{
					std::array<double, 4> y = {x[0], x[1], x[2], x[3]};
					y[j] += sign * steps[j];
					if (std::find(met.begin(), met.end(), y) != met.end()) continue;
					met.push_back(y);
					const double v = borderContrast(smooth, y[0], y[1], y[2], y[3]);
					if (y[2] > 2 && v > best) best = v, std::copy(y.begin(), y.end(), x), improved = true;
				}
		}
	}
	std::vector<cv::Point2f> q;
	for (int k = 0; k < 4; k++)
	{
		// Corner k: half a side out along two neighbouring normals. Back to
		// OpenCV's pixel convention like the other quads.
		const double a = x[3] + k * M_PI / 2, b = a + M_PI / 2;
		q.emplace_back(static_cast<float>(x[0] + x[2] * (std::cos(a) + std::cos(b)) - 0.5),
					   static_cast<float>(x[1] + x[2] * (std::sin(a) + std::sin(b)) - 0.5));
	}
	return q;
}

/** An image's pixel noise over its contrast: the robust standard deviation
 *  of neighbouring pixels' differences (most neighbours lie within one
 *  cell, not across an edge) over the difference of the mean grey levels
 *  on either side of `threshold`. Measured on candidate images lightly
 *  smoothed: 0.005-0.05 on the devset's and the observe bench's scans
 *  (Livox at most 0.084), 0.06-0.19 on the dense noisy walk's. */
double speckleOverContrast(const cv::Mat& gray8, double threshold)
{
	std::array<size_t, 256> steps{}, levels{};
	for (int r = 0; r < gray8.rows; r++)
	{
		const uint8_t* p = gray8.ptr<uint8_t>(r);
		levels[p[0]]++;
		for (int c = 1; c < gray8.cols; c++)
		{
			steps[static_cast<size_t>(std::abs(p[c] - p[c - 1]))]++;
			levels[p[c]]++;
		}
	}
	size_t pairs = 0, below = 0, above = 0;
	double sumBelow = 0, sumAbove = 0;
	for (size_t v = 0; v < 256; v++)
	{
		pairs += steps[v];
		(v <= threshold ? below : above) += levels[v];
		(v <= threshold ? sumBelow : sumAbove) += static_cast<double>(v * levels[v]);
	}
	if (pairs == 0 || below == 0 || above == 0) return 0;
	size_t medianStep = 0;
	for (size_t seen = 0; medianStep < 256 && (seen += steps[medianStep]) * 2 < pairs;) medianStep++;
	// 1.4826 x MAD is a Gaussian's sigma; a difference of two pixels has sqrt(2) of one's.
	const double noise = 1.4826 * static_cast<double>(medianStep) / std::sqrt(2.0);
	return noise / std::max(1.0, sumAbove / static_cast<double>(above) - sumBelow / static_cast<double>(below));
}

/** Pixel noise above this share of the contrast: a light smoothing's Otsu
 *  threshold breaks a tag's border ring (0.11 on the dense walk's images
 *  at the median, 0.013 on the observe bench's). */
constexpr double kSpeckled = 0.05;

/** Outlines of dark blobs under a global threshold. The contour finder in
 *  OpenCV's ArUco works on thin adaptive thresholds and misses a blurred
 *  tag's border; Otsu keeps the wide black border ring as one blob whose
 *  outline is the border square. */
void addDarkBlobOutlines(const cv::Mat& gray8, std::vector<std::vector<cv::Point2f>>& quads, double minArea)
{
	// A light smoothing keeps small tags' corners. On a speckled image (a
	// dense map's many points a pixel, each with its own intensity noise)
	// it leaves the border ring in fragments, and a heavier one (about two
	// point spacings: a pixel is 0.6 of one) joins it; elsewhere that second
	// pass found no tag the first missed and cost a tenth of the decode
	// (docs/PERFORMANCE.md, stop 44).
	std::vector<std::vector<cv::Point>> contours;
	cv::Mat smooth;  // sigma 1: what the border-square fit measures contrast on
	cv::GaussianBlur(gray8, smooth, cv::Size(), 1.0);
	cv::Mat dark;
	const double otsu = cv::threshold(smooth, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
	cv::findContours(dark, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
	if (speckleOverContrast(smooth, otsu) > kSpeckled)
	{
		cv::GaussianBlur(gray8, dark, cv::Size(), 3.0);
		cv::threshold(dark, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
		std::vector<std::vector<cv::Point>> found;
		cv::findContours(dark, found, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
		contours.insert(contours.end(), found.begin(), found.end());
	}
	// Both smoothings outline most blobs alike: a seed within half a pixel
	// of one already fitted would climb to the same square again.
	std::vector<cv::RotatedRect> fitted;
	const auto fittedBefore = [&](const cv::RotatedRect& r) {
		return std::any_of(fitted.begin(), fitted.end(), [&](const cv::RotatedRect& f) {
			return cv::norm(f.center - r.center) < 0.5 && std::abs(f.size.width - r.size.width) < 0.5 &&
				   std::abs(f.size.height - r.size.height) < 0.5 && std::abs(f.angle - r.angle) < 0.5;
		});
	};
	for (const auto& c : contours)
	{
		if (cv::contourArea(c) < minArea) continue;
		// The hull once: the smallest rectangle around the hull is the
		// contour's (minAreaRect would take the whole contour's hull again).
		std::vector<cv::Point> hull, poly;
		cv::convexHull(c, hull);
		// A blob too ragged for four corners may still be most of a
		// blurred tag: the square its edges fit best is a quad too.
		const cv::RotatedRect box = cv::minAreaRect(hull);
		if (box.size.width < 2 * box.size.height && box.size.height < 2 * box.size.width && !fittedBefore(box))
		{
			quads.push_back(fitBorderSquare(smooth, box));
			fitted.push_back(box);
		}
		// Blurred outlines are ragged: simplify their convex hull, loosening
		// the tolerance until four corners remain.
		for (double eps = 0.02; eps <= 0.12 && poly.size() != 4; eps += 0.01)
			cv::approxPolyDP(hull, poly, eps * cv::arcLength(hull, true), true);
		if (poly.size() != 4 || cv::contourArea(poly) < 0.8 * cv::contourArea(hull)) continue;
		std::vector<cv::Point2f> q;
		for (const auto& p : poly) q.emplace_back(p);
		// Contour pixels are the blob's outermost dark pixels: their outer edge is half a pixel out.
		const cv::Point2f centre = (q[0] + q[1] + q[2] + q[3]) * 0.25f;
		for (auto& p : q)
		{
			const cv::Point2f d = p - centre;
			p += d * (0.5f / std::max(1.0f, static_cast<float>(cv::norm(d))));
		}
		quads.push_back(q);
	}
}
/** The same outline found twice (by both finders, or as OpenCV's accepted
 *  and rejected candidate) decodes twice; the first one found is kept. */
std::vector<std::vector<cv::Point2f>> withoutDuplicates(const std::vector<std::vector<cv::Point2f>>& quads)
{
	std::vector<std::vector<cv::Point2f>> out;
	for (const auto& q : quads)
	{
		const double side = std::sqrt(std::max(cv::contourArea(q), 1.0));
		auto same = [&](const std::vector<cv::Point2f>& o) {
			for (const auto& p : q)
			{
				double nearest = 1e30;
				for (const auto& r : o) nearest = std::min(nearest, static_cast<double>(cv::norm(p - r)));
				if (nearest > std::max(1.5, 0.05 * side)) return false;
			}
			return true;
		};
		if (std::none_of(out.begin(), out.end(), same)) out.push_back(q);
	}
	return out;
}
}  // namespace

std::vector<Quad> findTagQuads(const cv::Mat& gray8, int maxQuads, double minSide)
{
	// Without a smallest side: a candidate image is mostly tag, and outlines
	// under 0.2 % of it (perimeters under 5 % of its edge) are specks.
	const double longEdge = std::max(gray8.cols, gray8.rows);
	const double minArea = minSide > 0 ? minSide * minSide : 0.002 * static_cast<double>(gray8.total());
	// The dictionary only decides which candidates OpenCV calls accepted;
	// both lists are quads to us, the identification happens later.
	std::vector<std::vector<cv::Point2f>> accepted, quads;
	std::vector<int> ids;
	auto detParams = cv::aruco::DetectorParameters::create();
	detParams->minMarkerPerimeterRate = minSide > 0 ? std::min(0.05, 4 * minSide / longEdge) : 0.05;
	// Adaptive thresholds over 13 and 23 pixel windows, not also OpenCV's
	// 3: our images are splatted and blurred over about a pixel or more,
	// where a 3-pixel window compares a pixel with its own blur. Its
	// outlines were a third of this search and changed nothing: without
	// them the same JSON on 24 randomized maps and the 9 devset maps, one
	// more sighting in 200 spinning scans' views (docs/PERFORMANCE.md).
	detParams->adaptiveThreshWinSizeMin = 13;
	detParams->adaptiveThreshWinSizeMax = 23;
	cv::aruco::detectMarkers(gray8, cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), accepted, ids, detParams,
							 quads);
	quads.insert(quads.begin(), accepted.begin(), accepted.end());  // first: kept where both lists hold an outline
	addDarkBlobOutlines(gray8, quads, minArea);
	quads = withoutDuplicates(quads);
	std::stable_sort(quads.begin(), quads.end(),
					 [](const auto& a, const auto& b) { return cv::contourArea(a) > cv::contourArea(b); });
	if (static_cast<int>(quads.size()) > maxQuads) quads.resize(static_cast<size_t>(std::max(0, maxQuads)));
	std::vector<Quad> out;
	for (const auto& q : quads)
	{
		Quad c;
		for (int k = 0; k < 4; k++) c[k] = Eigen::Vector2d(q[k].x + 0.5, q[k].y + 0.5);  // OpenCV -> our pixel convention
		out.push_back(c);
	}
	return out;
}

std::vector<Quad> scaledQuads(const std::vector<Quad>& quads, double factor)
{
	std::vector<Quad> out = quads;
	for (Quad& q : out)
		for (auto& c : q) c *= factor;
	return out;
}

Quad orderedCorners(const Quad& q, int order)
{
	Quad c;
	const bool mirrored = order >= 4;
	for (int k = 0; k < 4; k++) c[k] = q[mirrored ? (order - k + 8) % 4 : (order + k) % 4];
	return c;
}

namespace
{
// Homography from grid coordinates (cells) to the image, for a quad that
// outlines the grid square [first, last).
cv::Matx33d gridToImage(const Quad& q, int first, int last)
{
	const float b0 = static_cast<float>(first), b1 = static_cast<float>(last);
	const std::vector<cv::Point2f> src = {{b0, b0}, {b1, b0}, {b1, b1}, {b0, b1}};
	std::vector<cv::Point2f> dst;
	for (const auto& p : q) dst.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
	return cv::getPerspectiveTransform(src, dst);
}

std::vector<float> sampleGrid(const cv::Mat& gray8, const cv::Mat* measured, const Quad& q, int cells, int first,
							  int last)
{
	const cv::Matx33d H = gridToImage(q, first, last);
	const GrayPixels pixels(gray8);
	std::vector<float> sample(static_cast<size_t>(cells * cells));
	for (int r = 0; r < cells; r++)
		for (int col = 0; col < cells; col++)
		{
			// 3 x 3 points in the cell's middle: away from the blurred edges.
			double acc = 0;
			int cnt = 0, measuredCount = 0;
			for (double dy : {0.3, 0.5, 0.7})
				for (double dx : {0.3, 0.5, 0.7})
				{
					const cv::Vec3d p = H * cv::Vec3d(col + dx, r + dy, 1.0);
					const double x = p[0] / p[2], y = p[1] / p[2];
					const double v = sampleBilinear(pixels, x, y);
					if (v < 0) continue;
					cnt++;
					if (measured && !measured->at<uint8_t>(static_cast<int>(y), static_cast<int>(x))) continue;
					acc += v;
					measuredCount++;
				}
			if (cnt == 0) return {};
			sample[static_cast<size_t>(r * cells + col)] =
				measuredCount > 0 ? static_cast<float>(acc / measuredCount) : std::numeric_limits<float>::quiet_NaN();
		}
	return sample;
}
}  // namespace

Quad gridSquareIn(const Quad& q, int first, int last, int from, int to)
{
	if (first == from && last == to) return q;
	const cv::Matx33d H = gridToImage(q, first, last);
	const double f = from, t = to;
	const std::array<cv::Vec3d, 4> grid = {cv::Vec3d(f, f, 1), cv::Vec3d(t, f, 1), cv::Vec3d(t, t, 1), cv::Vec3d(f, t, 1)};
	Quad out;
	for (int k = 0; k < 4; k++)
	{
		const cv::Vec3d p = H * grid[static_cast<size_t>(k)];
		out[k] = Eigen::Vector2d(p[0] / p[2], p[1] / p[2]);
	}
	return out;
}

std::vector<float> sampleCells(const cv::Mat& gray8, const Quad& q, int cells, int first, int last)
{
	return sampleGrid(gray8, nullptr, q, cells, first, last);
}

std::vector<float> sampleMeasuredCells(const cv::Mat& gray8, const cv::Mat& measured, const Quad& q, int cells,
									   int first, int last)
{
	CV_Assert(measured.type() == CV_8UC1 && measured.size() == gray8.size());
	return sampleGrid(gray8, &measured, q, cells, first, last);
}

const std::vector<int>& cellPermutation(int cells, int order)
{
	static std::mutex m;
	static std::map<std::pair<int, int>, std::vector<int>> cache;
	std::lock_guard<std::mutex> lock(m);
	auto& perm = cache[{cells, order}];
	if (!perm.empty()) return perm;
	// Order `order` maps grid corner k to the quad corner that order 0 calls
	// idx(k); the same symmetry of the square moves every cell centre.
	const double n = cells;
	const Quad square = {Eigen::Vector2d(0, 0), Eigen::Vector2d(n, 0), Eigen::Vector2d(n, n), Eigen::Vector2d(0, n)};
	const Quad to = orderedCorners(square, order);
	// Affine map with to[0] at (0,0), to[1] at (n,0), to[3] at (0,n).
	const Eigen::Vector2d ex = (to[1] - to[0]) / n, ey = (to[3] - to[0]) / n;
	perm.resize(static_cast<size_t>(cells * cells));
	for (int r = 0; r < cells; r++)
		for (int c = 0; c < cells; c++)
		{
			const Eigen::Vector2d p = to[0] + ex * (c + 0.5) + ey * (r + 0.5);
			perm[static_cast<size_t>(r * cells + c)] =
				static_cast<int>(std::floor(p.y())) * cells + static_cast<int>(std::floor(p.x()));
		}
	return perm;
}

}  // namespace tagmap
