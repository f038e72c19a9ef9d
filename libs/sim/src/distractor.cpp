#include "tagmap/sim/distractor.h"

#include <algorithm>
#include <cmath>

#include "tagmap/sim/non_tag_interior.h"
#include "tagmap/sim/rng.h"
#include "tagmap/tag_family.h"

namespace tagmap::sim
{
namespace
{
// Texture cells per `cell` along each axis: a window's mullion is a fifth
// of its pitch, every other kind draws whole cells.
int subdivisions(DistractorKind k) { return k == DistractorKind::WindowGrid ? 5 : 1; }

// A QR code's finder: 7 x 7 dark ring, light ring, 3 x 3 dark centre.
template <class Set>
void finder(int top, int left, float dark, float light, Set set)
{
	for (int r = 0; r < 7; r++)
		for (int c = 0; c < 7; c++)
		{
			const int ring = std::min(std::min(r, c), std::min(6 - r, 6 - c));
			set(top + r, left + c, ring == 1 ? light : dark);
		}
}

// The whole sheet is one grid of cells; returns cells[r][c] in {dark, light}.
void fillPattern(const DistractorSpec& s, Texture& t)
{
	Rng rng(streamSeed(s.seed, kStreamScene, 0xD157));
	std::uniform_real_distribution<double> u(0, 1);
	t.cells.assign(static_cast<size_t>(t.cols) * t.rows, t.base);
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
		case DistractorKind::WindowGrid:
		{
			// Whole windows only, closed by a mullion on every side.
			const int k = subdivisions(s.kind);
			const int wr = (t.rows - 1) / k, wc = (t.cols - 1) / k;
			for (int r = 0; r < wr * k; r++)
				for (int c = 0; c < wc * k; c++)
					if (r % k && c % k) set(r, c, s.dark);
			break;
		}
		case DistractorKind::Zebra:
			// Bars in the odd columns, one cell of asphalt at both ends;
			// worn paint: each cell of a bar 70-100 % of `light`.
			for (int c = 1; c < t.cols; c += 2)
				for (int r = 1; r + 1 < t.rows; r++) set(r, c, static_cast<float>(s.light * (0.7 + 0.3 * u(rng))));
			break;
		case DistractorKind::QrLike:
		{
			constexpr int q = 2;  // quiet zone, modules
			const int n = std::min(t.rows, t.cols) - 2 * q;
			for (int r = 0; r < n; r++)
				for (int c = 0; c < n; c++)
				{
					const bool inFinder = (r < 8 && c < 8) || (r < 8 && c >= n - 8) || (r >= n - 8 && c < 8);
					if (inFinder) continue;  // finder and its light separator
					const bool timing = r == 6 || c == 6;
					set(q + r, q + c, (timing ? (r + c) % 2 == 0 : u(rng) < s.fill) ? s.dark : s.light);
				}
			auto put = [&](int r, int c, float v) { set(q + r, q + c, v); };
			finder(0, 0, s.dark, s.light, put);
			finder(0, n - 7, s.dark, s.light, put);
			finder(n - 7, 0, s.dark, s.light, put);
			break;
		}
		case DistractorKind::BorderedSquare:
		{
			const int n = std::min(t.rows, t.cols) - 4;  // inside quiet zone and border
			const std::vector<bool> inside = nonTagInterior(n, s.seed);
			for (int r = 1; r < n + 3; r++)
				for (int c = 1; c < n + 3; c++)
				{
					const bool border = r == 1 || c == 1 || r == n + 2 || c == n + 2;
					set(r, c, border || inside[(r - 2) * n + (c - 2)] ? s.dark : s.light);
				}
			break;
		}
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

int cellsIn(double length, double cell) { return static_cast<int>(std::floor(length / cell * (1 + 1e-12))); }

int minCellsAcross(DistractorKind kind)
{
	switch (kind)
	{
		case DistractorKind::QrLike:
			return 19;
		case DistractorKind::BorderedSquare:
			return 7;
		case DistractorKind::WindowGrid:
			return 2;
		default:
			return 0;  // any sheet holds the older kinds (at least one cell is drawn)
	}
}

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
	const bool darkGround = s.kind == DistractorKind::Stripes || s.kind == DistractorKind::Zebra;
	t.base = darkGround ? s.dark : s.light;
	const double cell = s.cell / subdivisions(s.kind);
	// The older kinds keep plain floor(), a rounding short of a whole cell
	// included, so the shipped scenes' maps stay byte-identical (negatives'
	// 0.49 x 0.35 m checker_7x5 of 0.07 m cells is drawn 7 x 4); the kinds
	// that need a number of cells count them as the scene means them.
	auto count = [&](double length) {
		return minCellsAcross(s.kind) > 0 ? cellsIn(length, cell) : static_cast<int>(std::floor(length / cell));
	};
	t.cols = std::max(1, count(s.width));
	t.rows = std::max(1, count(s.height));
	t.cellW = t.cellH = cell;
	t.left = -0.5 * t.cols * cell;
	t.top = 0.5 * t.rows * cell;
	fillPattern(s, t);

	SceneObject o;
	o.name = s.name;
	o.kind = ObjectKind::Distractor;
	o.faces.push_back(std::move(r));
	return o;
}

}  // namespace tagmap::sim
