#include "tagmap/soft_decoder.h"

#include <algorithm>
#include <cmath>
#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "tagmap/apriltag_families.h"
#include "tagmap/tag_family.h"

namespace tagmap
{
// Every code of a family as a zero-mean, unit-norm vector over its cells,
// so a dot product with a normalised sample is their Pearson correlation.
struct SoftTagDecoder::FamilyCodes
{
	int cells = 0, borderStart = 0, borderCells = 0;
	std::vector<int> informative;  // cells whose colour differs between codes
	std::vector<float> unit;  // idCount x informative.size()
	std::vector<uint8_t> borderMask;  // 1: a border-ring cell (black), 2: a quiet-zone cell (white)
	int idCount = 0;
};

namespace
{
void normalise(std::vector<float>& v, size_t begin, size_t n)
{
	double mean = 0, ss = 0;
	for (size_t i = 0; i < n; i++) mean += v[begin + i];
	mean /= static_cast<double>(n);
	for (size_t i = 0; i < n; i++) ss += (v[begin + i] - mean) * (v[begin + i] - mean);
	const double inv = ss > 0 ? 1.0 / std::sqrt(ss) : 0.0;
	for (size_t i = 0; i < n; i++) v[begin + i] = static_cast<float>((v[begin + i] - mean) * inv);
}

double sampleBilinear(const cv::Mat& img, double x, double y)
{
	// Image coordinates with pixel centres on half-integers.
	x -= 0.5;
	y -= 0.5;
	if (x < 0 || y < 0 || x >= img.cols - 1 || y >= img.rows - 1) return -1;
	const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
	const double fx = x - x0, fy = y - y0;
	const uint8_t* a = img.ptr<uint8_t>(y0);
	const uint8_t* b = img.ptr<uint8_t>(y0 + 1);
	return (1 - fy) * ((1 - fx) * a[x0] + fx * a[x0 + 1]) + fy * ((1 - fx) * b[x0] + fx * b[x0 + 1]);
}
}  // namespace

SoftTagDecoder::SoftTagDecoder(const std::vector<std::string>& families, SoftDecoderParams params)
	: params_(params), requested_(families), families_(searchFamilies(families))
{
}

SoftTagDecoder::~SoftTagDecoder() = default;

const SoftTagDecoder::FamilyCodes& SoftTagDecoder::codesOf(const std::string& family) const
{
	auto& slot = codes_[family];
	if (slot) return *slot;
	slot = std::make_unique<FamilyCodes>();
	FamilyCodes& fc = *slot;
	const TagFamilyInfo* info = findFamily(family);
	fc.idCount = info->idCount;
	const TagBitmap first = renderTagBitmap(family, 0);
	fc.cells = first.cells;
	fc.borderStart = first.borderStart;
	fc.borderCells = first.borderCells;
	const size_t all = static_cast<size_t>(fc.cells * fc.cells);
	std::vector<TagBitmap> bitmaps;
	std::vector<int> whiteCount(all, 0);
	for (int id = 0; id < fc.idCount; id++)
	{
		bitmaps.push_back(renderTagBitmap(family, id));
		for (size_t i = 0; i < all; i++) whiteCount[i] += bitmaps.back().pixels[i] ? 1 : 0;
	}
	// Cells that are the same in every code carry no information about the
	// id; leaving them out makes the correlation tell codes apart.
	for (size_t i = 0; i < all; i++)
		if (whiteCount[i] != 0 && whiteCount[i] != fc.idCount) fc.informative.push_back(static_cast<int>(i));
	const size_t n = fc.informative.size();
	fc.unit.resize(n * static_cast<size_t>(fc.idCount));
	for (int id = 0; id < fc.idCount; id++)
	{
		for (size_t j = 0; j < n; j++) fc.unit[id * n + j] = bitmaps[id].pixels[fc.informative[j]] / 255.0f;
		normalise(fc.unit, id * n, n);
	}
	// Cells every code shares: the border ring is black, the quiet zone white.
	fc.borderMask.assign(all, 0);
	for (int r = 0; r < fc.cells; r++)
		for (int c = 0; c < fc.cells; c++)
		{
			const bool quiet = r == 0 || c == 0 || r == fc.cells - 1 || c == fc.cells - 1;
			const int b0 = fc.borderStart, b1 = fc.borderStart + fc.borderCells - 1;
			const bool ring = (r == b0 || r == b1 || c == b0 || c == b1) && r >= b0 && r <= b1 && c >= b0 && c <= b1;
			fc.borderMask[r * fc.cells + c] = quiet ? 2 : (ring && first.at(r, c) == 0 ? 1 : 0);
		}
	return fc;
}

std::vector<DecodedTag2D> SoftTagDecoder::decode(const cv::Mat& gray8) const
{
	std::vector<DecodedTag2D> out;
	if (!params_.enabled || families_.empty()) return out;

	// Quads: every convex square-ish contour the ArUco detector considered.
	std::vector<std::vector<cv::Point2f>> accepted, rejected;
	std::vector<int> ids;
	auto detParams = cv::aruco::DetectorParameters::create();
	detParams->minMarkerPerimeterRate = 0.05;
	cv::aruco::detectMarkers(gray8, cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), accepted, ids, detParams,
							 rejected);
	for (auto& q : accepted) rejected.push_back(q);
	// The contour finder above works on thin adaptive thresholds and misses
	// a blurred tag's border; a global (Otsu) threshold keeps the wide black
	// border ring as one blob whose outline is the border square.
	cv::Mat dark;
	cv::GaussianBlur(gray8, dark, cv::Size(), 1.0);
	cv::threshold(dark, dark, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
	std::vector<std::vector<cv::Point>> contours;
	cv::findContours(dark, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
	const double minArea = 0.002 * gray8.total();
	for (const auto& c : contours)
	{
		// Blurred outlines are ragged: simplify their convex hull, loosening
		// the tolerance until four corners remain.
		if (cv::contourArea(c) < minArea) continue;
		std::vector<cv::Point> hull, poly;
		cv::convexHull(c, hull);
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
		rejected.push_back(q);
	}
	std::sort(rejected.begin(), rejected.end(), [](const auto& a, const auto& b) {
		return cv::contourArea(a) > cv::contourArea(b);
	});
	if (static_cast<int>(rejected.size()) > params_.maxQuads) rejected.resize(params_.maxQuads);

	for (const auto& quad : rejected)
	{
		// The 8 ways the quad's corners can be the tag's TL, TR, BR, BL.
		std::array<Eigen::Vector2d, 4> q;
		for (int k = 0; k < 4; k++) q[k] = Eigen::Vector2d(quad[k].x + 0.5, quad[k].y + 0.5);  // OpenCV -> our pixel convention
		for (const auto& family : families_)
		{
			const FamilyCodes& fc = codesOf(family);
			const size_t n = static_cast<size_t>(fc.cells * fc.cells), ni = fc.informative.size();
			if (ni == 0) continue;
			std::vector<float> data(ni);
			double best = -2, second = -2;
			int bestId = -1, bestOrder = -1;
			for (int order = 0; order < 8; order++)
			{
				const bool mirrored = order >= 4;
				std::array<Eigen::Vector2d, 4> c;
				for (int k = 0; k < 4; k++) c[k] = q[mirrored ? (order - (k) + 8) % 4 : (order + k) % 4];
				// Homography from grid coordinates (cells) to the image.
				const double b0 = fc.borderStart, b1 = fc.borderStart + fc.borderCells;
				std::vector<cv::Point2f> src = {{float(b0), float(b0)}, {float(b1), float(b0)}, {float(b1), float(b1)},
												{float(b0), float(b1)}};
				std::vector<cv::Point2f> dst;
				for (const auto& p : c) dst.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
				const cv::Matx33d H = cv::getPerspectiveTransform(src, dst);
				std::vector<float> sample(n);
				bool inside = true;
				for (int r = 0; r < fc.cells && inside; r++)
					for (int col = 0; col < fc.cells && inside; col++)
					{
						double acc = 0;
						int cnt = 0;
						for (double dy : {0.3, 0.5, 0.7})
							for (double dx : {0.3, 0.5, 0.7})
							{
								const cv::Vec3d g(col + dx, r + dy, 1.0);
								const cv::Vec3d p = H * g;
								const double v = sampleBilinear(gray8, p[0] / p[2], p[1] / p[2]);
								if (v < 0) continue;
								acc += v;
								cnt++;
							}
						if (cnt == 0) inside = false;
						sample[r * fc.cells + col] = static_cast<float>(acc / std::max(cnt, 1));
					}
				if (!inside) continue;
				// Shared cells first: a dark ring inside a light quiet zone, or this is no tag of this family.
				double ring = 0, quiet = 0;
				int nr = 0, nq = 0;
				for (size_t i = 0; i < n; i++)
				{
					if (fc.borderMask[i] == 1) ring += sample[i], nr++;
					if (fc.borderMask[i] == 2) quiet += sample[i], nq++;
				}
				if (nr == 0 || nq == 0 || ring / nr + 20 > quiet / nq) continue;
				for (size_t j = 0; j < ni; j++) data[j] = sample[fc.informative[j]];
				normalise(data, 0, ni);
				for (int id = 0; id < fc.idCount; id++)
				{
					const float* u = &fc.unit[id * ni];
					double dot = 0;
					for (size_t j = 0; j < ni; j++) dot += u[j] * data[j];
					if (dot > best)
					{
						if (!(bestId == id)) second = best;
						best = dot;
						bestId = id;
						bestOrder = order;
					}
					else if (dot > second && id != bestId)
						second = dot;
				}
			}
			if (bestId < 0 || best < params_.minCorrelation || best - second < params_.minGap) continue;
			DecodedTag2D d;
			d.family = reportedFamily(requested_, family, bestId);
			if (d.family.empty()) continue;
			d.id = bestId;
			d.mirrored = bestOrder >= 4;
			for (int k = 0; k < 4; k++) d.corners[k] = q[d.mirrored ? (bestOrder - k + 8) % 4 : (bestOrder + k) % 4];
			d.margin = 100 * best;
			d.hamming = -1;  // not a bit decode
			out.push_back(d);
		}
	}
	return out;
}

}  // namespace tagmap
