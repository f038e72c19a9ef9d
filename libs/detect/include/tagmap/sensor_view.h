// Stages 1-3 for a single scan in its own sensor frame (the fast path of
// `tagmap observe`): the scan seen from its sensor.
//
// A map merged from many viewpoints has no single view in which every tag
// shows; that is why the paper looks for tags through the 3D intensity
// gradient. A scan has one viewpoint (its sensor, at the origin), and from
// there nothing occludes a tag the scan measured: one spherical intensity
// image of the whole scan shows every tag it holds. The decoders read that
// image once; each read becomes a box around the tag's 3D corners, and
// only those boxes go on to the map path's stages 4-7 (gather, intermediate
// plane, decode, every 3D check). The sensor view only proposes: what it
// reads is never reported without the same checks a map's candidate gets.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "tagmap/clustering.h"
#include "tagmap/tag_decoder.h"

namespace tagmap
{
struct SensorViewParams
{
	/** Off: every scan goes through the map path. */
	bool enabled = false;
	/** Pixel edge, in the scan's angular spacing (sqrt of the solid angle
	 *  the scan covers per point; the intermediate plane uses 0.6 too). */
	double pixelSpacings = 0.6;
	/** Gaussian splat sigma, in the scan's angular spacing. */
	double splatSpacings = 0.6;
	/** Holes are filled up to this blur sigma, in angular spacings: across
	 *  scan lines and rosette gaps, not across the sky. */
	double fillSpacings = 4;
	/** Azimuth repeated past the seam of a 360 deg scan, degrees: a tag
	 *  straddling it is whole on one side. */
	double seamOverlapDeg = 20;
	/** Image edge cap, pixels (a finer image is coarsened to fit). */
	int maxImagePixels = 4096;
	/** libapriltag searches the view's quads on an image this many times
	 *  coarser (then fits them at full resolution): 2 x 0.6 spacings is
	 *  about the points' own spacing, the finest detail they resolve. */
	double quadDecimate = 2;
	/** Tag-shaped quads tried per view by ArUco and the soft decoder (the
	 *  candidate images' cap is for one tag's neighbourhood; a view holds
	 *  the whole scan). */
	int maxQuads = 64;
	/** The scan's points kept around each read, in quad sides beyond its
	 *  bounding rectangle (pointsNearReads()); the lengths are measured
	 *  and the tags verified on those alone. */
	double nearSides = 3;
};

/** The scan projected onto azimuth (columns, decreasing to the right, so
 *  the image is the scene as the sensor sees it) and elevation (rows,
 *  decreasing downwards). */
struct SensorView
{
	cv::Mat gray;  // CV_8UC1, contrast-normalised like the intermediate plane
	double pixel = 0;  // radians per pixel
	double azimuthLeft = 0, elevationTop = 0;  // radians at pixel edge (0, 0)
	double angularSpacing = 0;  // radians, sqrt(solid angle covered / points)
	/** Each point's image coordinates (pixel edges on integers); a point
	 *  repeated past the seam keeps its first position. */
	std::vector<Eigen::Vector2f> pixelOf;

	/** Unit direction from the sensor through image point `xy`. */
	Eigen::Vector3d ray(const Eigen::Vector2d& xy) const;
};

/** Renders the scan (sensor at the origin) as seen from the sensor; an
 *  empty image when it covers no solid angle (fewer than 16 points). */
SensorView renderSensorView(const float* xs, const float* ys, const float* zs, const float* is, size_t n,
							const SensorViewParams& p);

/** The box a read of the view proposes, in the form the map path's stage 3
 *  gives (clustering.h): centred on the tag's 3D corners (their rays cut
 *  the plane of the points inside the quad), length and width the printed
 *  tag's (the border square and its one-cell quiet zone) plus `band` on
 *  each side, height (and thickness) 4x the RMS of
 *  those points about the plane. `points`: the scan's points to look
 *  among (ascending; all of them, or pointsNearReads(), which holds every
 *  point inside a read's quad). `corners` (optional): those 3D corners,
 *  in the read's order. False when fewer than 8 points fall inside the
 *  quad or a corner's ray misses that plane. */
bool boxOfRead(const SensorView& view, const DecodedTag2D& read, const float* xs, const float* ys, const float* zs,
			   const std::vector<uint32_t>& points, double band, OrientedBox& box,
			   std::array<Eigen::Vector3d, 4>* corners = nullptr);

/** The scan's points (indices) seen within `sides` quad sides of a read:
 *  each read's quad, its bounding rectangle widened by `sides` times its
 *  longer side on every side. Everything the map path's stages 4-7 look at
 *  around a tag (its gathered box, the support plane 1.5 tag sizes out,
 *  the columns 3 tag sizes in front) lies there; the rest of the scan
 *  only costs time. Ascending, each index once. */
std::vector<uint32_t> pointsNearReads(const SensorView& view, const std::vector<DecodedTag2D>& reads, double sides);

}  // namespace tagmap
