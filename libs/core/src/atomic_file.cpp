#include "tagmap/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "tagmap/errors.h"

namespace fs = std::filesystem;

namespace tagmap
{
namespace
{
std::string temporaryNameFor(const std::string& path)
{
	std::random_device rd;
	return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
}
}  // namespace

void checkOutputWritable(const std::string& path)
{
	if (path.empty()) throw InputError("output path is empty");
	const fs::path p(path);
	if (fs::is_directory(p)) throw InputError(path, "", "is a directory, expected a file name");
	fs::path dir = p.parent_path();
	if (dir.empty()) dir = ".";
	std::error_code ec;
	fs::create_directories(dir, ec);
	if (ec) throw InputError(path, "", "cannot create folder " + dir.string() + ": " + ec.message());
	if (::access(dir.c_str(), W_OK) != 0)
		throw InputError(path, "", "folder " + dir.string() + " is not writable: " + std::strerror(errno));
	// access() says yes to root everywhere, and to folders like /proc where no
	// file can be made: create (and remove) the temporary file for real.
	const std::string probe = temporaryNameFor(path);
	const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
	if (fd < 0) throw InputError(path, "", "cannot create a file in folder " + dir.string() + ": " + std::strerror(errno));
	::close(fd);
	::unlink(probe.c_str());
}

void writeFileAtomicallyByName(const std::string& path, const std::function<void(const std::string&)>& write)
{
	checkOutputWritable(path);
	const std::string tmp = temporaryNameFor(path);
	try
	{
		write(tmp);
	}
	catch (...)
	{
		std::error_code ec;
		fs::remove(tmp, ec);
		throw;
	}
	std::error_code ec;
	fs::rename(tmp, path, ec);
	if (ec)
	{
		fs::remove(tmp, ec);
		throw InputError(path, "", "cannot rename temporary file into place: " + ec.message());
	}
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
	writeFileAtomicallyByName(path, [&](const std::string& tmp) {
		std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
		if (!out) throw InputError(path, "", "cannot open for writing: " + std::string(std::strerror(errno)));
		write(out);
		out.flush();
		if (!out) throw InputError(path, "", "write failed (disk full?)");
		out.close();
		if (out.fail()) throw InputError(path, "", "write failed while closing");
	});
}

}  // namespace tagmap
