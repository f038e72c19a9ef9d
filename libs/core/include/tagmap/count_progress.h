// The progress callback of a stage that works through a known number of
// items (points, rays, scans, filter steps): items done so far, items in all.
// Each stage says what its items are and whether it calls from worker threads.
#pragma once

#include <cstddef>
#include <functional>

namespace tagmap
{
using CountProgressFn = std::function<void(size_t done, size_t total)>;
}  // namespace tagmap
