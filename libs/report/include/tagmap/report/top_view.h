// The whole map in one picture: points projected onto the map's dominant
// plane (the XY plane when that plane is roughly horizontal, as for most
// outdoor and SLAM maps, so north stays up), coloured by intensity, the
// nearest point winning each pixel, with every found tag outlined and
// labelled "family:id".
#pragma once

#include <mrpt/maps/CPointsMapXYZI.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::report
{
struct TopViewParams
{
	int maxPixels = 1600;  // longest image edge
	/** Empty pixels take their neighbours' value, as many times as the map's
	 *  point spacing spans pixels (at most this), so a sparse map or a
	 *  close-up reads as surfaces rather than dust. */
	int maxFillIterations = 8;
	double loPercent = 2, hiPercent = 98;  // intensity normalisation
	int colormap = cv::COLORMAP_VIRIDIS;  // perceptually uniform, colour-blind safe
	/** Dominant-plane normal within this angle of z: use the XY plane. */
	double horizontalToleranceDeg = 30;
};

/** Where map points land in the picture: viewer looks along -n; u is the
 *  image's right, v its up (u x v = n). */
struct ViewFrame
{
	Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY(), n = Eigen::Vector3d::UnitZ();
	double uMin = 0, vMax = 0;  // map coordinates of the top-left corner
	double pixel = 1;  // metres per pixel
	cv::Point2d toPixel(const Eigen::Vector3d& p) const { return {(p.dot(u) - uMin) / pixel, (vMax - p.dot(v)) / pixel}; }
};

struct TopView
{
	cv::Mat image;  // CV_8UC3 BGR
	ViewFrame frame;
	std::string caption;  // what the picture shows, for people
};

TopView renderTopView(const mrpt::maps::CPointsMapXYZI& map, const std::vector<TagDetection>& tags,
					  const TopViewParams& p = {});

}  // namespace tagmap::report
