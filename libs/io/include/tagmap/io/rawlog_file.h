// Reading and writing whole rawlog files (tagmap detect, observe, localize). MRPT's own
// CRawlog::loadFromRawLogFile() prints a multi-line exception with a stack
// trace to stderr on a bad file and only returns false; tagmap promises one
// line naming the file, so the objects are read here one by one.
#pragma once

#include <mrpt/obs/CRawlog.h>

#include <string>

namespace tagmap::io
{
/** Throws InputError "<path>: <what>" for a missing, unreadable or empty file. */
mrpt::obs::CRawlog loadRawlog(const std::string& path);

/** Writes `log` (gz) atomically. */
void saveRawlog(const std::string& path, const mrpt::obs::CRawlog& log);

}  // namespace tagmap::io
