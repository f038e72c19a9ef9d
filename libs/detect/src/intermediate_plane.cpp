#include "tagmap/intermediate_plane.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tagmap/point_stats.h"

namespace tagmap
{
namespace
{
// A pixel is scanned when a point lies within one splat sigma of it (that
// point's weight there is at least exp(-1/2)). Not where the summed splats
// reach 5 % (`known`, 2 sigma and more along dense lines): in a gap between
// sparse scan lines (a Livox rosette) that paints the gap with the colour
// of the line beside it, and a tag's border ring in the gap reads as its
// quiet zone.
const float kScannedWeight = static_cast<float>(std::exp(-0.5));

/** A Gaussian blur of sigma `s` pixels. Wide blurs run on a copy shrunk so
 *  that sigma is ~2 pixels there, then are enlarged back: a hole-filling
 *  blur of sigma 64 would otherwise cost a 385-tap filter per pixel (it was
 *  the decode stage's single largest cost). */
cv::Mat blurredAtScale(const cv::Mat& img, double s)
{
	cv::Mat out;
	const double shrink = std::floor(s / 2);
	if (shrink < 2 || std::min(img.cols, img.rows) < 2 * shrink)
	{
		cv::GaussianBlur(img, out, cv::Size(), s);
		return out;
	}
	cv::Mat small;
	cv::resize(img, small, cv::Size(), 1 / shrink, 1 / shrink, cv::INTER_AREA);
	cv::GaussianBlur(small, small, cv::Size(), s / shrink);
	cv::resize(small, out, img.size(), 0, 0, cv::INTER_LINEAR);
	return out;
}
/** exp(-d^2 k) at d = d0, d0 + 1, ..., `count` of them: each from the one
 *  before, g(d + 1) = g(d) exp(-(2d + 1) k), whose factor shrinks by
 *  exp(-2k) = `ratio` a step: two exps for a row of taps, not one per tap. */
void gaussianTaps(double d0, int count, double k, double ratio, double* out)
{
	double g = std::exp(-d0 * d0 * k), factor = std::exp(-(2 * d0 + 1) * k);
	for (int j = 0; j < count; j++)
	{
		out[j] = g;
		g *= factor;
		factor *= ratio;
	}
}
}  // namespace

void normalisedMean(const cv::Mat& wsum, const cv::Mat& isum, float eps, float knownAbove, cv::Mat& img, cv::Mat& known)
{
	img.create(wsum.size(), CV_32F);
	known.create(wsum.size(), CV_8U);
	for (int r = 0; r < wsum.rows; r++)
	{
		const float* w = wsum.ptr<float>(r);
		const float* i = isum.ptr<float>(r);
		float* value = img.ptr<float>(r);
		uint8_t* isKnown = known.ptr<uint8_t>(r);
		for (int c = 0; c < wsum.cols; c++)
		{
			value[c] = i[c] / (w[c] + eps);
			isKnown[c] = w[c] > knownAbove ? 255 : 0;
		}
	}
}

void fillHoles(const cv::Mat& wsum, const cv::Mat& isum, double firstSigma, double maxSigma, cv::Mat& img,
			   cv::Mat& known)
{
	// One pass over the pixels per scale: the unknown ones the blurred
	// weights reach take the blurred mean (a chain of whole-image
	// operations here cost more than the blurs themselves).
	size_t unknown = known.total() - static_cast<size_t>(cv::countNonZero(known));
	for (double s = firstSigma; unknown > 0 && s < maxSigma; s *= 2)
	{
		const cv::Mat bw = blurredAtScale(wsum, s), bi = blurredAtScale(isum, s);
		for (int r = 0; r < img.rows; r++)
		{
			const float* w = bw.ptr<float>(r);
			const float* i = bi.ptr<float>(r);
			float* value = img.ptr<float>(r);
			uint8_t* isKnown = known.ptr<uint8_t>(r);
			for (int c = 0; c < img.cols; c++)
				if (!isKnown[c] && w[c] > 1e-4f)
				{
					value[c] = i[c] / (w[c] + 1e-9f);
					isKnown[c] = 255;
					unknown--;
				}
		}
	}
}

cv::Mat contrastNormalised(const cv::Mat& img, std::vector<float> intensities, const cv::Mat& known)
{
	// The points' own intensities set the contrast: the image does not
	// depend on the sensor's intensity scale. Ranks in ascending order:
	// each selection searches only above the one before (already partitioned).
	size_t from = 0;
	const auto at = [&](size_t k) {
		const auto first = intensities.begin() + static_cast<std::ptrdiff_t>(from);
		std::nth_element(first, intensities.begin() + static_cast<std::ptrdiff_t>(k), intensities.end());
		from = k;
		return static_cast<double>(intensities[k]);
	};
	const size_t n = intensities.size();
	const double lo8 = at(n * 2 / 100), mid = at(n / 2), hi8 = at(n * 98 / 100);
	const double scale = hi8 > lo8 ? 255.0 / (hi8 - lo8) : 1.0;
	cv::Mat gray;
	img.convertTo(gray, CV_8U, scale, -lo8 * scale);
	gray.setTo(cv::Scalar(static_cast<int>(std::clamp((mid - lo8) * scale, 0.0, 255.0))), ~known);
	return gray;
}

PlaneImage renderIntermediatePlane(const float* xs, const float* ys, const float* zs, const float* is,
								   const std::vector<uint32_t>& points, const OrientedBox& box, double spacing,
								   const IntermediatePlaneParams& p, double smallestCell)
{
	PlaneImage out;
	if (points.size() < 16) return out;

	// Robust plane: start from the cluster box, keep points near the plane,
	// refit, and tighten to a few residual RMS. Walls behind a board, and
	// mixed-pixel points in between, fall out after the first rounds.
	Eigen::Vector3d c = box.center, n = box.axes.col(2);
	double tol = std::max(0.5 * box.extent.z(), 2 * spacing) + 2 * spacing;
	std::vector<uint32_t> in, before;
	PlaneFit fit{c, n, tol};
	for (int iter = 0; iter < 5; iter++)
	{
		in.swap(before);
		in.clear();
		for (uint32_t i : points)
			if (std::abs((Eigen::Vector3d(xs[i], ys[i], zs[i]) - c).dot(n)) <= tol) in.push_back(i);
		if (in.size() < 16) return out;
		// The same points as the round before: the same fit, and every
		// round after would select them again.
		if (iter > 0 && in == before) break;
		fit = fitPlane(xs, ys, zs, in);
		c = fit.centroid;
		// Keep the side the box chose: which side is "front" is decided by
		// the decoder (raw or mirrored read), not by an eigenvector's sign.
		n = fit.normal.dot(box.axes.col(2)) >= 0 ? fit.normal : Eigen::Vector3d(-fit.normal);
		tol = std::max(p.inlierSigmas * fit.rms, 0.5 * spacing);
	}
	out.inliers = in;
	out.planeRms = fit.rms;

	// In-plane axes: the box's length direction projected onto the plane.
	PlaneFrame& fr = out.frame;
	fr.n = n;
	fr.u = (box.axes.col(0) - n * n.dot(box.axes.col(0))).normalized();
	fr.v = n.cross(fr.u);

	Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
	std::vector<Eigen::Vector2d> uv(in.size());
	for (size_t k = 0; k < in.size(); k++)
	{
		const Eigen::Vector3d d = Eigen::Vector3d(xs[in[k]], ys[in[k]], zs[in[k]]) - c;
		uv[k] = Eigen::Vector2d(d.dot(fr.u), d.dot(fr.v));
		lo = lo.cwiseMin(uv[k]);
		hi = hi.cwiseMax(uv[k]);
	}
	const double area = std::max((hi - lo).prod(), 1e-8);
	out.localSpacing = std::sqrt(area / static_cast<double>(in.size()));
	fr.pixel = std::max(p.pixelSpacings * out.localSpacing, (hi - lo).maxCoeff() / p.maxImagePixels);
	if (smallestCell > 0 && p.pixelsPerCell > 0) fr.pixel = std::max(fr.pixel, smallestCell / p.pixelsPerCell);
	const int pad = p.paddingPixels;
	const int W = static_cast<int>(std::ceil((hi.x() - lo.x()) / fr.pixel)) + 2 * pad;
	const int H = static_cast<int>(std::ceil((hi.y() - lo.y()) / fr.pixel)) + 2 * pad;
	// Pixel-edge (0, 0) is the top-left: smallest u, largest v.
	fr.origin = c + fr.u * (lo.x() - pad * fr.pixel) + fr.v * (hi.y() + pad * fr.pixel);

	// Gaussian splatting: each point spreads its intensity over nearby
	// pixels; the image is the weighted mean (normalised convolution).
	cv::Mat wsum(H, W, CV_32F, cv::Scalar(0)), isum(H, W, CV_32F, cv::Scalar(0));
	out.measured = cv::Mat(H, W, CV_8U, cv::Scalar(0));
	const double sigmaPx = std::max(0.5, p.splatSpacings * out.localSpacing / fr.pixel);
	const int rad = static_cast<int>(std::ceil(2 * sigmaPx));
	const double inv2s2 = 1.0 / (2 * sigmaPx * sigmaPx);
	std::vector<double> wx(static_cast<size_t>(2 * rad + 1)), wyTaps(wx.size());
	const double tapRatio = std::exp(-2 * inv2s2);
	std::vector<float> vals;
	vals.reserve(in.size());
	for (size_t k = 0; k < in.size(); k++)
	{
		const Eigen::Vector2d xy = fr.toImage(c + fr.u * uv[k].x() + fr.v * uv[k].y());
		const float I = is[in[k]];
		vals.push_back(I);
		const int cx = static_cast<int>(xy.x()), cy = static_cast<int>(xy.y());
		const int x0 = std::max(0, cx - rad), x1 = std::min(W - 1, cx + rad);
		const int y0 = std::max(0, cy - rad), y1 = std::min(H - 1, cy + rad);
		// The Gaussian is separable: its taps along a row and down a column,
		// not one per pixel (the exps were most of the render's time).
		gaussianTaps(x0 + 0.5 - xy.x(), x1 - x0 + 1, inv2s2, tapRatio, wx.data());
		gaussianTaps(y0 + 0.5 - xy.y(), y1 - y0 + 1, inv2s2, tapRatio, wyTaps.data());
		for (int y = y0; y <= y1; y++)
		{
			const double wy = wyTaps[static_cast<size_t>(y - y0)];
			float* ws = wsum.ptr<float>(y);
			float* iS = isum.ptr<float>(y);
			for (int x = x0; x <= x1; x++)
			{
				const float w = static_cast<float>(wx[static_cast<size_t>(x - x0)] * wy);
				ws[x] += w;
				iS[x] += w * I;
			}
			// A pixel's weight is at most its row's (wx <= 1): only rows
			// within a sigma of the point can hold a scanned pixel.
			if (static_cast<float>(wy) < kScannedWeight) continue;
			uint8_t* scanned = out.measured.ptr<uint8_t>(y);
			for (int x = x0; x <= x1; x++)
				if (static_cast<float>(wx[static_cast<size_t>(x - x0)] * wy) >= kScannedWeight) scanned[x] = 255;
		}
	}
	// Holes (occlusion shadows, sparse scan lines): fill from ever blurrier
	// versions of the same normalised convolution.
	cv::Mat img, known;
	normalisedMean(wsum, isum, 1e-6f, 0.05f, img, known);
	fillHoles(wsum, isum, 2 * sigmaPx, std::max(W, H), img, known);

	out.gray = contrastNormalised(img, std::move(vals), known);
	return out;
}

}  // namespace tagmap
