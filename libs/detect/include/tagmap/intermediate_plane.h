// Stage 5 (paper, Sec. II-E): move a candidate's points onto an
// intermediate plane and render an intensity image a camera decoder can read.
//
// The paper transforms the points into the box frame and projects them
// spherically from 1 m. We fit the tag plane (robustly, from all gathered
// points) and project orthographically onto it instead: the image is then
// a true-scale, distortion-free view whatever the map's viewpoints, pixel
// size follows the local point spacing, and mapping decoded corners back
// to 3D is exact (see docs/ARCHITECTURE.md for the measurements).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "tagmap/clustering.h"

namespace tagmap
{
struct IntermediatePlaneParams
{
	double pixelSpacings = 0.6;  // pixel edge, in local point spacings
	double splatSpacings = 0.6;  // Gaussian splat sigma, in local point spacings
	/** Image edge cap: a candidate holds one tag, and 200 pixels leave it
	 *  5-16 per cell; finer images of dense maps resolve the points' scatter
	 *  instead of averaging it (default.yaml has the numbers). */
	int maxImagePixels = 200;
	/** The finest image a decode needs: the smallest cell of any tag the
	 *  detection can report (renderIntermediatePlane's `smallestCell`) this
	 *  many pixels across. Maps denser than that (mm spacing) made images
	 *  sharper than any cell, and every image step costs per pixel. 0: no cap. */
	double pixelsPerCell = 10;
	double inlierSigmas = 3.0;  // plane inliers: |distance| <= this x residual RMS
	int paddingPixels = 8;  // uniform border so tags at the edge still decode
};

/** The tag plane with an in-plane frame: u right, v up, n = u x v towards
 *  the viewer of the (unmirrored) image. */
struct PlaneFrame
{
	Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // 3D point of image pixel-edge (0, 0)
	Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY(), n = Eigen::Vector3d::UnitZ();
	double pixel = 0.01;  // metres per pixel

	/** 3D point of image coordinates (x right, y down, pixel edges on integers). */
	Eigen::Vector3d toMap(const Eigen::Vector2d& xy) const { return origin + u * (xy.x() * pixel) - v * (xy.y() * pixel); }
	Eigen::Vector2d toImage(const Eigen::Vector3d& p) const
	{
		const Eigen::Vector3d d = p - origin;
		return {d.dot(u) / pixel, -d.dot(v) / pixel};
	}
};

struct PlaneImage
{
	PlaneFrame frame;
	cv::Mat gray;  // CV_8UC1, contrast-normalised (2nd..98th percentile)
	/** CV_8UC1, 255 within one splat sigma of a point (before hole
	 *  filling): what was scanned; the rest of `gray` is interpolated from
	 *  points further away. */
	cv::Mat measured;
	std::vector<uint32_t> inliers;  // map indices of the points on the plane
	double planeRms = 0;  // residual RMS of the plane fit, metres
	double localSpacing = 0;  // point spacing on the plane, metres
};

/** A normalised convolution's mean, `img` = isum / (wsum + eps), and where
 *  it is `known` (wsum > knownAbove), in one pass over the pixels. Shared
 *  by the intermediate plane and the sensor view. */
void normalisedMean(const cv::Mat& wsum, const cv::Mat& isum, float eps, float knownAbove, cv::Mat& img, cv::Mat& known);

/** Holes of a normalised convolution (`img` = isum / wsum where `known`):
 *  filled from ever blurrier versions of it, sigma `firstSigma` pixels,
 *  doubling while below `maxSigma` and pixels are unknown. Shared by the
 *  intermediate plane and the sensor view. */
void fillHoles(const cv::Mat& wsum, const cv::Mat& isum, double firstSigma, double maxSigma, cv::Mat& img,
			   cv::Mat& known);

/** `img` (float) as 8 bits: the 2nd..98th percentile of the rendered
 *  points' `intensities` stretched over 0..255, pixels not `known` at
 *  their median. Shared by the intermediate plane and the sensor view. */
cv::Mat contrastNormalised(const cv::Mat& img, std::vector<float> intensities, const cv::Mat& known);

/** Fits the plane, projects and renders. Returns an empty image when the
 *  points do not make a plane. `box` seeds the plane and the in-plane axes;
 *  `smallestCell` (metres, 0 = unknown) is the smallest tag cell the image
 *  must resolve: pixels need not be finer than smallestCell / pixelsPerCell. */
PlaneImage renderIntermediatePlane(const float* xs, const float* ys, const float* zs, const float* is,
								   const std::vector<uint32_t>& points, const OrientedBox& box, double spacing,
								   const IntermediatePlaneParams& p, double smallestCell = 0);

}  // namespace tagmap
