#include "tagmap/sim/distractor.h"

#include <algorithm>
#include <cmath>

#include "tagmap/sim/rng.h"
#include "tagmap/tag_family.h"

namespace tagmap::sim
{
namespace
{
// The whole sheet is one grid of cells; returns cells[r][c] in {dark, light}.
void fillPattern(const DistractorSpec& s, Texture& t)
{
	Rng rng(streamSeed(s.seed, kStreamScene, 0xD157));
	std::uniform_real_distribution<double> u(0, 1);
	t.cells.assign(static_cast<size_t>(t.cols) * t.rows, s.light);
	auto set = [&](int r, int c, float v) { t.cells[static_cast<size_t>(r) * t.cols + c] = v; };
	switch (s.kind)
	{
		case DistractorKind::Checkerboard:
			for (int r = 0; r < t.rows; r++)
				for (int c = 0; c < t.cols; c++) set(r, c, (r + c) % 2 ? s.light : s.dark);
			break;
		case DistractorKind::RandomBlocks:
			for (int r = 0; r < t.rows; r++)
				for (int c = 0; c < t.cols; c++) set(r, c, u(rng) < s.fill ? s.dark : s.light);
			break;
		case DistractorKind::Text:
			// Lines of "words": rows of 2-cell-high glyph blocks, 1-cell line
			// gaps, words of random length separated by blanks.
			for (int r = 1; r + 1 < t.rows; r += 3)
			{
				int c = 1;
				while (c < t.cols - 1)
				{
					const int word = 2 + static_cast<int>(u(rng) * 6);
					for (int k = 0; k < word && c < t.cols - 1; k++, c++)
						if (u(rng) < 0.5 + 0.5 * s.fill)
						{
							set(r, c, s.dark);
							if (u(rng) < 0.7) set(r + 1, c, s.dark);
						}
					c += 1;
				}
			}
			break;
		case DistractorKind::Stripes:
			for (int r = 0; r < t.rows; r++)
				for (int c = 0; c < t.cols; c++) set(r, c, c % 2 ? s.dark : s.light);
			break;
		case DistractorKind::MirroredTag:
		{
			const TagBitmap bm = renderTagBitmap(s.family, s.id);
			for (int r = 0; r < t.rows && r < bm.cells; r++)
				for (int c = 0; c < t.cols && c < bm.cells; c++) set(r, c, bm.at(r, bm.cells - 1 - c) ? s.light : s.dark);
			break;
		}
	}
}
}  // namespace

SceneObject makeDistractor(const DistractorSpec& spec)
{
	DistractorSpec s = spec;
	if (s.kind == DistractorKind::MirroredTag) s.cell = s.width / renderTagBitmap(s.family, s.id).cells;
	Rect r;
	r.pose = s.pose;
	r.pose.translate(Eigen::Vector3d(0, 0, s.offset));
	r.halfW = 0.5 * s.width;
	r.halfH = 0.5 * s.height;
	r.printedFrontOnly = true;
	Texture& t = r.texture;
	t.base = s.kind == DistractorKind::Stripes ? s.dark : s.light;
	t.cols = std::max(1, static_cast<int>(std::floor(s.width / s.cell)));
	t.rows = std::max(1, static_cast<int>(std::floor(s.height / s.cell)));
	t.cellW = t.cellH = s.cell;
	t.left = -0.5 * t.cols * s.cell;
	t.top = 0.5 * t.rows * s.cell;
	fillPattern(s, t);

	SceneObject o;
	o.name = s.name;
	o.kind = ObjectKind::Distractor;
	o.faces.push_back(std::move(r));
	return o;
}

}  // namespace tagmap::sim
