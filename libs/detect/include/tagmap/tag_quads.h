// Stage 5a: tag-shaped quadrilaterals in a candidate image, and the tag's
// cell grid sampled inside one. Found once per image and shared by the
// ArUco decoder (OpenCV's identify on the sampled bits) and the soft
// decoder (correlation with every code), instead of every dictionary
// re-running OpenCV's thresholding and contour search on the raw and on
// the mirrored image.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace tagmap
{
/** Four corners in our pixel convention (pixel (c, r) covers [c, c+1) x
 *  [r, r+1)), in the order the contour finder gave them. */
using Quad = std::array<Eigen::Vector2d, 4>;

/** Square-ish outlines: every candidate OpenCV's ArUco contour finder
 *  considers (thin adaptive thresholds), plus the outlines of dark blobs
 *  under a global Otsu threshold, which keep a blurred tag's black border
 *  ring whole. Largest first, at most `maxQuads`. `minSide` (pixels): the
 *  smallest outline kept; 0 for a candidate image, which is mostly tag
 *  (outlines under 0.2 % of its area are specks). A whole scan's view
 *  holds tags far smaller than itself and gives its own. */
std::vector<Quad> findTagQuads(const cv::Mat& gray8, int maxQuads, double minSide = 0);

/** `quads` in an image resized by `factor` (pixel edges scale exactly). */
std::vector<Quad> scaledQuads(const std::vector<Quad>& quads, double factor);

/** One of the 8 ways a quad's corners can be a tag's TL, TR, BR, BL:
 *  orders 0-3 rotate, 4-7 are the mirror images (the tag seen from behind). */
Quad orderedCorners(const Quad& q, int order);

/** The mean grey level of each cell of a `cells` x `cells` tag grid whose
 *  cells [first, last) span the quad (corners in order 0), row-major;
 *  empty when part of the grid falls outside the image. */
std::vector<float> sampleCells(const cv::Mat& gray8, const Quad& q, int cells, int first, int last);

/** The square of grid cells [from, to) x [from, to) in the image, for a
 *  quad `q` that outlines the square [first, last) x [first, last) (the
 *  homography of sampleCells()): e.g. a tag's border square inside the
 *  outline of the black ring around it. */
Quad gridSquareIn(const Quad& q, int first, int last, int from, int to);

/** sampleCells() from the pixels `measured` marks (CV_8UC1, non-zero: a
 *  point was scanned there; the image's size) only: a cell none of whose
 *  sample points is measured is NaN, an erasure (a gap in the scan the
 *  image's hole filling painted over is no evidence of a colour). */
std::vector<float> sampleMeasuredCells(const cv::Mat& gray8, const cv::Mat& measured, const Quad& q, int cells,
									   int first, int last);

/** Index map from the order-0 samples to those of `order`: sample k of
 *  order `order` is sample perm[k] of order 0. The grid is symmetric, so
 *  re-ordering the corners only permutes cells; no need to resample. */
const std::vector<int>& cellPermutation(int cells, int order);

}  // namespace tagmap
