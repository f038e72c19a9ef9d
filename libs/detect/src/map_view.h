// The map's points as the stages read them: four float arrays (MapView),
// and some of them copied into arrays of their own (PointsSubset). Private
// to tagmap_detect.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include <mrpt/maps/CPointsMapXYZI.h>

namespace tagmap::detail
{
// Everything one candidate needs from the map, in one place.
struct MapView
{
	const float *xs, *ys, *zs, *is;
	size_t n;

	explicit MapView(const mrpt::maps::CPointsMapXYZI& map)
		: xs(map.getPointsBufferRef_x().data()),
		  ys(map.getPointsBufferRef_y().data()),
		  zs(map.getPointsBufferRef_z().data()),
		  is(map.getPointsBufferRef_intensity().data()),
		  n(map.size())
	{
	}
	MapView(const float* x, const float* y, const float* z, const float* i, size_t count)
		: xs(x), ys(y), zs(z), is(i), n(count)
	{
	}
	Eigen::Vector3d point(uint32_t i) const { return {xs[i], ys[i], zs[i]}; }
};

// Some of a map's points, copied into a map of their own.
struct PointsSubset
{
	std::vector<uint32_t> indices;  // in the map they were copied from, ascending
	std::vector<float> xs, ys, zs, is;
	PointsSubset(const MapView& m, std::vector<uint32_t> from) : indices(std::move(from))
	{
		for (auto* v : {&xs, &ys, &zs, &is}) v->reserve(indices.size());
		for (uint32_t i : indices)
		{
			xs.push_back(m.xs[i]);
			ys.push_back(m.ys[i]);
			zs.push_back(m.zs[i]);
			is.push_back(m.is[i]);
		}
	}
	MapView view() const { return {xs.data(), ys.data(), zs.data(), is.data(), xs.size()}; }
};

}  // namespace tagmap::detail
