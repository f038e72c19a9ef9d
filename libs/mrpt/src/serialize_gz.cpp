#include "tagmap/mrpt/serialize_gz.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include "tagmap/atomic_file.h"

namespace tagmap::mrpt_bridge
{
namespace
{
void writeGz(const std::string& path, const std::function<void(mrpt::serialization::CArchive&)>& body)
{
	writeFileAtomicallyByName(path, [&](const std::string& tmpPath) {
		// The stream is closed (and the gzip trailer flushed) when it goes out
		// of scope, before writeFileAtomicallyByName renames the file.
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmpPath)) throw std::runtime_error(path + ": cannot open for writing");
		auto arch = mrpt::serialization::archiveFrom(f);
		body(arch);
	});
}
}  // namespace

void writeSerializableGz(const std::string& path, const mrpt::serialization::CSerializable& obj)
{
	writeGz(path, [&](mrpt::serialization::CArchive& a) { a << obj; });
}

void writeSerializableSequenceGz(const std::string& path,
								 const std::vector<mrpt::serialization::CSerializable::Ptr>& objects)
{
	writeGz(path, [&](mrpt::serialization::CArchive& a) {
		for (const auto& o : objects) a << *o;
	});
}

}  // namespace tagmap::mrpt_bridge
