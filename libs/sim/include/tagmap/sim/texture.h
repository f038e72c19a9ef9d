// Reflectivity painted on a rectangle: a uniform base value plus an optional
// grid of cells (a tag bitmap, a checkerboard, a poster...). Everything the
// LiDAR sees as "texture" is one of these, so tags and distractors go
// through exactly the same physics.
#pragma once

#include <cmath>
#include <vector>

namespace tagmap::sim
{
struct Texture
{
	float base = 0.5f;  // reflectivity outside the grid, 0..1
	int cols = 0, rows = 0;
	double cellW = 0, cellH = 0;  // metres
	double left = 0, top = 0;  // rectangle coordinates (u, v) of the grid's top-left corner
	std::vector<float> cells;  // row-major, row 0 at the top (largest v), reflectivity 0..1

	/** Reflectivity at rectangle coordinates (u right, v up). */
	float at(double u, double v) const
	{
		if (cells.empty()) return base;
		const double c = std::floor((u - left) / cellW);
		const double r = std::floor((top - v) / cellH);
		if (c < 0 || r < 0 || c >= cols || r >= rows) return base;
		return cells[static_cast<size_t>(r) * cols + static_cast<size_t>(c)];
	}
};

}  // namespace tagmap::sim
