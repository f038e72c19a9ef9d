// Writing a whole folder without ever leaving it half-written: it is built
// next to its destination and renamed into place once complete. Replacing a
// folder is the dangerous part (`--report ~` must not wipe a home folder), so
// an existing destination is only replaced when it is empty or carries the
// marker file that this function puts in every folder it writes.
#pragma once

#include <functional>
#include <string>

namespace tagmap::report
{
/** Throws InputError when `dir` could not be (re)placed: its parent is not
 *  writable, it is a file, or it is a non-empty folder without `marker`.
 *  Call before long computations. */
void checkDirectoryReplaceable(const std::string& dir, const std::string& marker);

/** Calls `fill` with a fresh temporary folder next to `dir`, adds `marker`,
 *  then swaps it into place. If `fill` throws, the temporary folder is
 *  removed, `dir` is untouched and the error is rethrown. */
void writeDirectoryAtomically(const std::string& dir, const std::string& marker,
							  const std::function<void(const std::string& tmpDir)>& fill);

}  // namespace tagmap::report
