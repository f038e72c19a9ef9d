#include "tagmap/io/rawlog_file.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"

namespace tagmap::io
{
mrpt::obs::CRawlog loadRawlog(const std::string& path)
{
	if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "no such file");
	mrpt::io::CFileGZInputStream in;
	if (!in.open(path)) throw InputError(path, "", "cannot open");
	auto archive = mrpt::serialization::archiveFrom(in);
	mrpt::obs::CRawlog log;
	for (size_t n = 0;; n++)
	{
		mrpt::serialization::CSerializable::Ptr obj;
		try
		{
			obj = archive.ReadObject();
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			break;
		}
		catch (const std::exception& e)
		{
			throw InputError(path, "object " + std::to_string(n + 1), "not a readable MRPT rawlog (" + errorSummary(e.what()) + ")");
		}
		log.insert(obj);
	}
	if (log.empty()) throw InputError(path, "", "empty rawlog");
	return log;
}

void saveRawlog(const std::string& path, const mrpt::obs::CRawlog& log)
{
	writeFileAtomicallyByName(path, [&](const std::string& tmp) {
		if (!log.saveToRawLogFile(tmp)) throw InputError(tmp, "", "cannot write rawlog");
	});
}

}  // namespace tagmap::io
