// Replays fuzz inputs (the seed corpus and every crash a fuzzer ever found)
// through a fuzz target built without libFuzzer, so the regular build and
// ctest keep each fixed crash fixed. Usage: fuzz_replay_X DIR_OR_FILE...
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
void replay(const std::filesystem::path& file)
{
	std::ifstream in(file, std::ios::binary);
	const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	std::printf("%s (%zu bytes)\n", file.string().c_str(), bytes.size());
	std::fflush(stdout);  // so a crash is attributed to the right file
	LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}
}  // namespace

int main(int argc, char** argv)
{
	size_t count = 0;
	for (int i = 1; i < argc; i++)
	{
		const std::filesystem::path p(argv[i]);
		if (!std::filesystem::exists(p)) continue;  // no regressions yet for this target
		if (!std::filesystem::is_directory(p))
		{
			replay(p);
			count++;
			continue;
		}
		for (const auto& e : std::filesystem::directory_iterator(p))
			if (e.is_regular_file() && e.path().filename().string()[0] != '.')
			{
				replay(e.path());
				count++;
			}
	}
	std::printf("replayed %zu inputs\n", count);
	return 0;
}
