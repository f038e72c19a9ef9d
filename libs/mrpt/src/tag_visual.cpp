#include "tagmap/mrpt/tag_visual.h"

#include <mrpt/opengl/CText.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>

#include "tagmap/tag_family.h"

namespace tagmap::mrpt_bridge
{
mrpt::img::CImage tagTextureImage(const std::string& family, int id, int pixelsPerCell)
{
	const TagBitmap bmp = renderTagBitmap(family, id);
	const int side = bmp.cells * pixelsPerCell;
	mrpt::img::CImage img(side, side, mrpt::img::CH_GRAY);
	for (int y = 0; y < side; y++)
	{
		const int row = bmp.cells - 1 - y / pixelsPerCell;  // flipped: see header
		auto* line = img.ptrLine<uint8_t>(static_cast<unsigned>(y));
		for (int x = 0; x < side; x++) line[x] = bmp.at(row, x / pixelsPerCell);
	}
	return img;
}

namespace
{
// The drawn square [lo, hi]^2 in the tag frame: the bitmap includes a quiet
// zone, placed so the border square spans [-s/2, s/2] as docs/RESULT_FORMAT.md
// defines the tag frame.
std::pair<double, double> drawnSpan(const TagDetection& tag, const TagBitmap& bmp)
{
	const double cell = tag.size / bmp.borderCells;
	const double lo = -bmp.centreInCells() * cell;
	return {lo, lo + bmp.cells * cell};
}
}  // namespace

double drawnHalfSide(const TagDetection& tag)
{
	const auto [lo, hi] = drawnSpan(tag, renderTagBitmap(tag.family, tag.id));
	return std::max(-lo, hi);
}

mrpt::opengl::CSetOfObjects::Ptr makeTagVisual(const TagDetection& tag, const TagVisualParams& params)
{
	auto out = mrpt::opengl::CSetOfObjects::Create();
	out->setName(tagLabel(tag.family, tag.id));

	Eigen::Matrix4d T = tag.pose.matrix();
	out->setPose(mrpt::poses::CPose3D::FromHomogeneousMatrix(mrpt::math::CMatrixDouble44(T)));

	const auto [lo, hi] = drawnSpan(tag, renderTagBitmap(tag.family, tag.id));
	auto plane = mrpt::opengl::CTexturedPlane::Create(lo, hi, lo, hi);
	plane->assignImage(tagTextureImage(tag.family, tag.id, params.pixelsPerCell));
	plane->enableTextureLinearInterpolation(false);
	out->insert(plane);

	if (params.showAxes)
		out->insert(mrpt::opengl::stock_objects::CornerXYZSimple(
			static_cast<float>(params.axesLengthPerSize * tag.size), 3.0f));

	if (params.showLabel)
	{
		auto label = mrpt::opengl::CText::Create(out->getName());
		label->setLocation(0, hi + 0.1 * tag.size, 0);
		label->setColor_u8(255, 0, 255);  // magenta: not in the jet colours of the points
		out->insert(label);
	}
	return out;
}

}  // namespace tagmap::mrpt_bridge
