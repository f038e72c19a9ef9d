// The interior of a bordered-square distractor: random cells that are
// provably no tag. A black-bordered square in a white quiet zone is exactly
// what every decoder looks for, so it is the hardest negative there is, but
// only if its bits are not (within a decoder's correction) a real code.
#pragma once

#include <cstdint>
#include <vector>

namespace tagmap::sim
{
/** n x n cells, row-major, true = black, drawn from `seed`; re-drawn until,
 *  in all 4 rotations and both mirror sides, the square differs from every
 *  code of every family whose data lies inside a black border of n + 2
 *  cells by at least max(1, ceil(minHamming / 2)) cells: beyond what any
 *  decoder corrects. (Families printing data outside their border,
 *  tagStandard* and tagCircle*, would also need all of it white: the
 *  quiet zone here.) Throws std::runtime_error if no draw passes (n < 3). */
std::vector<bool> nonTagInterior(int n, uint64_t seed);

/** Fewest cells in which an n x n interior (inside a black border of n + 2
 *  cells) differs from any code of the families checked, over the 8
 *  orientations; INT_MAX when no family has that layout. For tests. */
int distanceToNearestCode(const std::vector<bool>& interior, int n, bool relativeToMargin = false);

}  // namespace tagmap::sim
