// One MRPT object to a gz-compressed file, atomically. The format every
// MRPT tool reads with CFileGZInputStream (.gz maps, .3Dscene, .rawlog).
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <string>
#include <vector>

namespace tagmap::mrpt_bridge
{
/** Writes `obj` to `path` via a temporary file (tagmap::writeFileAtomicallyByName). */
void writeSerializableGz(const std::string& path, const mrpt::serialization::CSerializable& obj);

/** Writes the objects one after another (an observations-only rawlog). */
void writeSerializableSequenceGz(const std::string& path,
								 const std::vector<mrpt::serialization::CSerializable::Ptr>& objects);

}  // namespace tagmap::mrpt_bridge
