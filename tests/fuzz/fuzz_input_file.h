// The readers and the config loader take file names, as the apps use them,
// so fuzz inputs go through a real file: one per process, on tmpfs when
// there is one, rewritten for every input. Slower than a memory buffer, but
// it fuzzes exactly the code path users hit, mmap included.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace tagmap::fuzz
{
/** Writes `data` to this process's scratch file with extension `ext`
 *  (".pcd", ".yaml", ...) and returns its path. */
inline const std::string& writeInputFile(const uint8_t* data, size_t size, const char* ext)
{
	static const std::string path = [ext] {
		const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
		return dir + "/tagmap-fuzz-" + std::to_string(getpid()) + ext;
	}();
	std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
	return path;
}

}  // namespace tagmap::fuzz
