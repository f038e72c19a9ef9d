// Writing outputs without ever leaving a half-written or clobbered file:
// everything goes to a temporary file in the destination folder, which is
// renamed over the destination only once complete and flushed.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace tagmap
{
/** Creates missing parent folders and checks the destination folder is
 *  writable; throws InputError naming the path otherwise. Call it before
 *  long computations so an unwritable output is reported at once. */
void checkOutputWritable(const std::string& path);

/** Calls `write` with a stream on a temporary file next to `path`, then
 *  renames it into place. If `write` throws, or the stream fails, the
 *  temporary file is removed, `path` is untouched and the error is rethrown. */
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/** Same, for writers that need a file name (e.g. MRPT's serializers). */
void writeFileAtomicallyByName(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);

}  // namespace tagmap
