// Every malformed input is one InputError line naming the file: no crash,
// no hang, no allocation of what a header merely claims.
#include "test_io_helpers.h"

using namespace iotest;

namespace
{
std::string validPcd(const std::string& data, size_t n = 100) { return makePcd(samplePoints(n), xyziFields(), data); }

std::string replaced(std::string s, const std::string& from, const std::string& to)
{
	const size_t at = s.find(from);
	EXPECT_NE(at, std::string::npos) << from;
	return at == std::string::npos ? s : s.replace(at, from.size(), to);
}
}  // namespace

TEST(IoMalformed, MissingFileAndUnknownExtension)
{
	expectInputError(scratchPath("does_not_exist.pcd"), "cannot open");
	const std::string e57 = writeFile("cloud.e57", "ASTM-E57");
	expectInputError(e57, "unknown file extension '.e57'; supported: .pcd .ply");
	expectInputError(writeFile("noext", "x"), "no file extension");
}

TEST(IoMalformed, EmptyFiles)
{
	for (const std::string ext : {".pcd", ".ply", ".bin", ".xyzi", ".simplemap", ".las"}) expectInputError(writeFile("empty" + ext, ""), "empty");
}

TEST(IoMalformed, PcdWrongMagic)
{
	expectInputError(writeFile("png.pcd", "\x89PNG\r\n\x1a\n binary junk"), "not a PCD file");
	expectInputError(writeFile("ply.pcd", "ply\nformat ascii 1.0\n"), "line 1: not a PCD file");
}

TEST(IoMalformed, PcdWithoutIntensityNamesItsFields)
{
	const auto pts = samplePoints(10);
	const std::string pcd = makePcd(pts, {{"x"}, {"y"}, {"z"}, {"rgb", 'U', 4}}, "binary");
	expectInputError(writeFile("rgb.pcd", pcd), "line 3: no intensity field (looked for intensity reflectivity scalar_Intensity i); the fields are: x y z rgb");
}

TEST(IoMalformed, PcdMissingCoordinate)
{
	const std::string pcd = makePcd(samplePoints(3), {{"x"}, {"y"}, {"intensity"}}, "binary");
	expectInputError(writeFile("noz.pcd", pcd), "no z field; the fields are: x y intensity");
}

TEST(IoMalformed, PcdTruncatedBinary)
{
	const std::string pcd = validPcd("binary");
	expectInputError(writeFile("cut.pcd", pcd.substr(0, pcd.size() - 5)), "truncated: 100 points x 16 bytes need 1600 bytes of data, the file has 1595");
}

TEST(IoMalformed, PcdHeaderCutOff)
{
	const std::string pcd = validPcd("binary");
	expectInputError(writeFile("hdr.pcd", pcd.substr(0, pcd.find("POINTS"))), "header: no DATA line");
}

TEST(IoMalformed, PcdAbsurdPointCountIsNotAllocated)
{
	for (const std::string data : {"binary", "binary_compressed", "ascii"})
	{
		SCOPED_TRACE(data);
		std::string pcd = replaced(validPcd(data), "WIDTH 100", "WIDTH 1000000000000");
		pcd = replaced(pcd, "POINTS 100", "POINTS 1000000000000");
		expectInputError(writeFile(data + ".pcd", pcd), data == "ascii"			 ? "file ends after 100 of 1000000000000 points"
										 : data == "binary" ? "truncated: 1000000000000 points x 16 bytes need 16000000000000 bytes"
															: "does not match POINTS x point size = 16000000000000");
	}
	std::string huge = replaced(validPcd("binary"), "WIDTH 100", "WIDTH 18446744073709551615");
	huge = replaced(huge, "POINTS 100", "POINTS 18446744073709551615");
	expectInputError(writeFile("huge.pcd", huge), "absurdly large");
	expectInputError(writeFile("overflow.pcd", replaced(validPcd("binary"), "HEIGHT 1", "HEIGHT 99999999999999999999999")), "line 8: bad HEIGHT value");
}

TEST(IoMalformed, PcdPointCountMismatch)
{
	expectInputError(writeFile("wh.pcd", replaced(validPcd("binary"), "POINTS 100", "POINTS 99")),
					 "header: POINTS 99 does not match WIDTH x HEIGHT = 100 x 1");
	const std::string ascii = validPcd("ascii", 4);
	expectInputError(writeFile("fewer.pcd", replaced(replaced(ascii, "WIDTH 4", "WIDTH 5"), "POINTS 4", "POINTS 5")), "file ends after 4 of 5 points");
	expectInputError(writeFile("more.pcd", replaced(replaced(ascii, "WIDTH 4", "WIDTH 3"), "POINTS 4", "POINTS 3")),
					 "line 15: more data lines than POINTS 3");
}

TEST(IoMalformed, PcdBadTypeSizeCombos)
{
	for (const auto& [type, size] : std::vector<std::pair<std::string, std::string>>{{"F", "2"}, {"U", "3"}, {"I", "16"}, {"Q", "4"}})
	{
		SCOPED_TRACE(type + size);
		std::string pcd = replaced(validPcd("binary"), "SIZE 4 4 4 4", "SIZE 4 4 4 " + size);
		pcd = replaced(pcd, "TYPE F F F F", "TYPE F F F " + type);
		expectInputError(writeFile("t.pcd", pcd), "field intensity: TYPE " + type + " with SIZE " + size + " is not a valid PCD type");
	}
	expectInputError(writeFile("n.pcd", replaced(validPcd("binary"), "SIZE 4 4 4 4", "SIZE 4 4 4")), "line 4: SIZE has 3 entries but FIELDS has 4");
	expectInputError(writeFile("c.pcd", replaced(validPcd("binary"), "COUNT 1 1 1 1", "COUNT 1 1 1 0")), "field intensity: COUNT 0 is out of range");
	expectInputError(writeFile("s.pcd", replaced(replaced(validPcd("binary"), "COUNT 1 1 1 1", "COUNT 1 1 1 2"), "SIZE 4 4 4 4", "SIZE 4 4 4 four")),
					 "line 4: bad SIZE value 'four'");
	expectInputError(writeFile("c2.pcd", replaced(validPcd("binary"), "COUNT 1 1 1 1", "COUNT 1 2 1 1")), "field y: has COUNT 2, expected 1");
	expectInputError(writeFile("d.pcd", replaced(validPcd("binary"), "DATA binary", "DATA binary_lz4")), "line 11: unknown DATA kind 'binary_lz4'");
	expectInputError(writeFile("k.pcd", replaced(validPcd("binary"), "VIEWPOINT", "VIEWPORT")), "line 9: unknown header keyword 'VIEWPORT'");
}

TEST(IoMalformed, PcdAsciiBadValues)
{
	const std::string ascii = validPcd("ascii", 3);
	const size_t data = ascii.find("DATA ascii\n") + 11;
	expectInputError(writeFile("v.pcd", ascii.substr(0, data) + "1 2 3\n"), "line 12: 3 values, the header declares 4 per point");
	expectInputError(writeFile("w.pcd", ascii.substr(0, data) + "1 2 abc 4\n"), "line 12: field z: 'abc' is not a number");
}

TEST(IoMalformed, PcdCompressedCorruption)
{
	const std::string good = validPcd("binary_compressed", 500);
	const size_t data = good.find("DATA binary_compressed\n") + 23;
	uint32_t sizes[2];
	std::memcpy(sizes, good.data() + data, 8);

	expectInputError(writeFile("cut.pcd", good.substr(0, good.size() - 10)), "truncated: compressed block of");
	expectInputError(writeFile("nosize.pcd", good.substr(0, data + 5)), "compressed-size words are missing");

	std::string wrongSize = good;
	const uint32_t bigger = sizes[1] + 16;
	std::memcpy(&wrongSize[data + 4], &bigger, 4);
	expectInputError(writeFile("usize.pcd", wrongSize), "byte offset " + std::to_string(data + 4) + ": uncompressed size");

	// A valid count with a compressed block far too short to produce it.
	std::string ratio = replaced(replaced(good, "WIDTH 500", "WIDTH 100000000"), "POINTS 500", "POINTS 100000000");
	const size_t data2 = ratio.find("DATA binary_compressed\n") + 23;
	const uint32_t claimed = 1600000000u;
	std::memcpy(&ratio[data2 + 4], &claimed, 4);
	expectInputError(writeFile("ratio.pcd", ratio), "is impossible for");

	std::string garbled = good;
	for (size_t k = data + 8; k < data + 8 + 40; ++k) garbled[k] = static_cast<char>(0xff);
	expectInputError(writeFile("garbled.pcd", garbled), "corrupt LZF data");
}

TEST(IoMalformed, PlyCases)
{
	const std::string props = "property float x\nproperty float y\nproperty float z\nproperty float intensity\n";
	expectInputError(writeFile("magic.ply", "solid cube\n"), "line 1: not a PLY file");
	expectInputError(writeFile("be.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 1\n" + props + "end_header\n"),
					 "line 2: binary_big_endian PLY is not supported");
	expectInputError(writeFile("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + props), "header: no end_header line");
	expectInputError(writeFile("rgb.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
										  "property uchar red\nend_header\n1 2 3 4\n"),
					 "line 3: no intensity field (looked for intensity reflectivity scalar_Intensity i); the fields are: x y z red");
	expectInputError(writeFile("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n"),
					 "line 4: unknown property type 'float128'");

	std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n" + props + "end_header\n";
	binary += std::string(32, '\0');
	expectInputError(writeFile("absurd.ply", binary), "truncated in element vertex");

	std::string lists = "ply\nformat binary_little_endian 1.0\nelement face 1000000000000\nproperty list uint int idx\nelement vertex 1\n" +
						props + "end_header\n";
	appendRaw(lists, static_cast<uint32_t>(4000000000u));
	expectInputError(writeFile("list.ply", lists), "truncated in element face (record 0 of 1000000000000)");

	std::string negative = "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list char int idx\nelement vertex 1\n" + props +
						   "end_header\n";
	appendRaw(negative, static_cast<int8_t>(-3));
	expectInputError(writeFile("negative.ply", negative), "byte offset " + std::to_string(negative.size() - 1) + ": element face: negative list length");

	expectInputError(writeFile("short.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + props + "end_header\n1 2 3 4\n"),
					 "line 10: file ends in element vertex after 1 of 3 records");
	expectInputError(writeFile("nan.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + props + "end_header\n1 2 x 4\n"),
					 "line 9: property z: 'x' is not a number");
	expectInputError(writeFile("extra.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + props + "end_header\n1 2 3 4 5\n"),
					 "line 9: 5 values, the vertex properties need 4");
}

TEST(IoMalformed, KittiSizeNotMultipleOf16)
{
	expectInputError(writeFile("odd.bin", std::string(16 * 3 + 7, '\0')), "byte offset 48: file size 55 is not a multiple of 16 bytes");
}

TEST(IoMalformed, XyziText)
{
	expectInputError(writeFile("xyz.xyz", "# header\n1 2 3\n"), "line 2: 3 values (x y z): no intensity column");
	expectInputError(writeFile("five.txt", "1 2 3 4\n1 2 3 4 5\n"), "line 2: 5 values, expected 4");
	expectInputError(writeFile("word.xyzi", "1 2 3 4\n1 2 three 4\n"), "line 2: 'three' is not a number");
	expectInputError(writeFile("comments.xyzi", "# only\n# comments\n"), "no points in the file");
}

TEST(IoMalformed, SimplemapGarbage)
{
	expectInputError(writeFile("junk.simplemap", std::string("this is not an MRPT archive at all, just text\n")), "not a readable MRPT simplemap");
	std::string gzJunk = "\x1f\x8b\x08";
	gzJunk += std::string(40, 'q');
	expectInputError(writeFile("gzjunk.simplemap", gzJunk), "not a readable MRPT simplemap");
}

TEST(IoMalformed, DirectoryIsNotAFile)
{
	const std::string dir = scratchPath("folder.pcd");
	std::filesystem::create_directories(dir);
	expectInputError(dir, "is not a regular file");
}

TEST(IoMalformed, CutsAndCorruptionNeverCrash)
{
	const auto pts = samplePoints(300);
	std::string plyBinary = "ply\nformat binary_little_endian 1.0\nelement vertex 300\nproperty float x\nproperty float y\nproperty float z\n"
							"property float intensity\nelement face 1\nproperty list uchar int idx\nend_header\n";
	for (const auto& p : pts)
		for (float v : {p.x, p.y, p.z, p.i}) appendRaw(plyBinary, v);
	const std::vector<std::pair<std::string, std::string>> files{
		{".pcd", makePcd(pts, xyziFields(), "ascii")},
		{".pcd", makePcd(pts, xyziFields(), "binary")},
		{".pcd", makePcd(pts, {{"x", 'F', 8}, {"_", 'U', 1, 3}, {"y"}, {"z"}, {"i", 'U', 2}}, "binary_compressed", "i")},
		{".ply", plyBinary},
		{".bin", std::string(plyBinary.end() - 16 * 300, plyBinary.end())},
	};
	uint32_t seed = 12345;
	auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
	size_t errors = 0, loads = 0;
	for (size_t f = 0; f < files.size(); ++f)
	{
		const std::string& good = files[f].second;
		std::vector<std::string> variants;
		for (size_t cut = 0; cut < good.size(); cut += good.size() / 40 + 1) variants.push_back(good.substr(0, cut));
		for (int k = 0; k < 60; ++k)
		{
			std::string bad = good;
			const size_t at = next() % std::min<size_t>(bad.size(), 400);  // mostly headers and the LZF stream start
			bad[at] = static_cast<char>(next());
			variants.push_back(bad);
		}
		for (size_t v = 0; v < variants.size(); ++v)
		{
			const std::string path = writeFile("f" + std::to_string(f) + files[f].first, variants[v]);
			try
			{
				mrpt::maps::CPointsMapXYZI map;
				tagmap::io::loadPointCloud(path, map);
				++loads;
			}
			catch (const tagmap::InputError& e)
			{
				++errors;
				EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
			}
			catch (const std::exception& e)
			{
				ADD_FAILURE() << "file " << f << " variant " << v << ": not an InputError: " << e.what();
			}
		}
	}
	EXPECT_GT(errors, 150u);  // the cuts alone are errors
	EXPECT_GT(loads, 10u);  // byte flips inside values still load
}
