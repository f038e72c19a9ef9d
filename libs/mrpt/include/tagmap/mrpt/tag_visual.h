// How a tag looks in MRPT's 3D viewers: its real printed pattern (from
// tagmap::renderTagBitmap, never redrawn) on a square in the tag plane, an
// "family:id" label and the tag frame's axes. Shared by CTagMap's
// getVisualizationInto(), the .3Dscene writer and the rawlog writer, so
// every viewer shows tags the same way.
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include "tagmap/tag_detection.h"

namespace tagmap::mrpt_bridge
{
struct TagVisualParams
{
	bool showLabel = true;
	bool showAxes = true;
	double axesLengthPerSize = 0.6;  // axes length as a fraction of the tag size
	int pixelsPerCell = 8;  // texture is nearest-neighbour upscaled so cells stay crisp
};

/** The tag bitmap as an image whose row 0 is the bottom row of the upright
 *  pattern: MRPT's CTexturedPlane maps image row 0 to the plane's yMin. */
mrpt::img::CImage tagTextureImage(const std::string& family, int id, int pixelsPerCell);

/** Half the side of the square makeTagVisual() draws: the whole bitmap,
 *  quiet zone (or outer data ring) included, in metres. */
double drawnHalfSide(const TagDetection& tag);

/** A set of objects posed at T_G_tag. Throws std::invalid_argument for a
 *  family or id renderTagBitmap() does not know. */
mrpt::opengl::CSetOfObjects::Ptr makeTagVisual(const TagDetection& tag, const TagVisualParams& params = {});

}  // namespace tagmap::mrpt_bridge
