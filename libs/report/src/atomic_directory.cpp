#include "tagmap/report/atomic_directory.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "tagmap/errors.h"

namespace fs = std::filesystem;

namespace tagmap::report
{
namespace
{
fs::path siblingName(const fs::path& dir, const char* what)
{
	std::random_device rd;
	fs::path p = dir;
	p += std::string(".") + what + "-" + std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
	return p;
}

// Trailing slashes ("out/report/") would make the rename target "out/report/."
fs::path normalised(const std::string& dir)
{
	fs::path p = fs::path(dir).lexically_normal();
	if (p.filename().empty()) p = p.parent_path();
	return p;
}
}  // namespace

void checkDirectoryReplaceable(const std::string& dir, const std::string& marker)
{
	if (dir.empty()) throw InputError("output folder path is empty");
	const fs::path p = normalised(dir);
	std::error_code ec;
	if (fs::exists(p, ec) && !fs::is_directory(p, ec)) throw InputError(dir, "", "exists and is not a folder");
	if (fs::is_directory(p, ec) && !fs::is_empty(p, ec) && !fs::exists(p / marker, ec))
		throw InputError(dir, "",
						 "exists and was not written by tagmap (no " + marker + "); choose a new or empty folder");
	fs::path parent = fs::absolute(p).parent_path();
	fs::create_directories(parent, ec);
	if (ec) throw InputError(dir, "", "cannot create folder " + parent.string() + ": " + ec.message());
	if (::access(parent.c_str(), W_OK) != 0)
		throw InputError(dir, "", "folder " + parent.string() + " is not writable: " + std::strerror(errno));
}

void writeDirectoryAtomically(const std::string& dir, const std::string& marker,
							  const std::function<void(const std::string&)>& fill)
{
	checkDirectoryReplaceable(dir, marker);
	const fs::path dest = normalised(dir), tmp = siblingName(dest, "tmp");
	std::error_code ec;
	try
	{
		fs::create_directory(tmp);
		fill(tmp.string());
		std::ofstream(tmp / marker) << "written by tagmap; this folder may be replaced by the next run\n";
	}
	catch (...)
	{
		fs::remove_all(tmp, ec);
		throw;
	}
	// rename() cannot replace a non-empty folder: move the old one aside
	// first. Between the two renames `dir` is briefly absent, never partial.
	fs::path old;
	if (fs::exists(dest, ec))
	{
		old = siblingName(dest, "old");
		fs::rename(dest, old, ec);
		if (ec)
		{
			fs::remove_all(tmp, ec);
			throw InputError(dir, "", "cannot move the previous folder aside: " + ec.message());
		}
	}
	fs::rename(tmp, dest, ec);
	if (ec)
	{
		const std::string why = ec.message();
		if (!old.empty()) fs::rename(old, dest, ec);
		fs::remove_all(tmp, ec);
		throw InputError(dir, "", "cannot rename the new folder into place: " + why);
	}
	if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace tagmap::report
