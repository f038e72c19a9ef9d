#include "tagmap/code_in_points.h"

#include <cmath>
#include <limits>

#include "tagmap/tag_family.h"

namespace tagmap
{
std::vector<float> cellMeansFromPoints(const TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys,
									   const float* zs, const float* is)
{
	const TagBitmap bm = renderTagBitmap(t.family, t.id);
	const double cell = t.size / bm.borderCells;
	const double toCentre = bm.centreInCells();
	const Eigen::Isometry3d toTag = t.pose.inverse();
	std::vector<double> sum(bm.pixels.size(), 0);
	std::vector<int> count(bm.pixels.size(), 0);
	for (uint32_t i : plane.inliers)
	{
		const Eigen::Vector3d l = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		const double col = l.x() / cell + toCentre, row = -l.y() / cell + toCentre;
		if (col < 0 || row < 0 || col >= bm.cells || row >= bm.cells) continue;
		const size_t k = static_cast<size_t>(row) * static_cast<size_t>(bm.cells) + static_cast<size_t>(col);
		sum[k] += is[i];
		count[k]++;
	}
	std::vector<float> means(bm.pixels.size(), std::numeric_limits<float>::quiet_NaN());
	for (size_t k = 0; k < means.size(); k++)
		if (count[k] > 0) means[k] = static_cast<float>(sum[k] / count[k]);
	return means;
}

std::vector<float> eraseUnmeasured(std::vector<float> cells, const std::vector<float>& pointMeans)
{
	if (cells.size() != pointMeans.size()) return {};
	for (size_t k = 0; k < cells.size(); k++)
		if (std::isnan(pointMeans[k])) cells[k] = std::numeric_limits<float>::quiet_NaN();
	return cells;
}

}  // namespace tagmap
