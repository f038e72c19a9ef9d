// Reading every supported format and encoding, from files the tests write.
#include <limits>

#include "tagmap/io/lzf.h"
#include "test_io_helpers.h"

using namespace iotest;
using tagmap::io::loadPointCloud;
using tagmap::io::LoadReport;

TEST(IoRoundTrip, SavePcdBinaryThenLoad)
{
	const auto pts = samplePoints(1000);
	mrpt::maps::CPointsMapXYZI map;
	for (const auto& p : pts) map.insertPointRGB(p.x, p.y, p.z, p.i, 0, 0);
	const std::string path = scratchPath("cloud.pcd");
	tagmap::io::savePcdBinary(path, map);
	LoadReport r;
	const auto back = loadPointCloud(path, &r);
	expectMapHolds(back, pts, 0);
	EXPECT_EQ(r.format, "pcd-binary");
	EXPECT_EQ(r.intensityField, "intensity");
	EXPECT_EQ(r.pointsRead, 1000u);
	EXPECT_EQ(r.pointsKept, 1000u);
}

TEST(IoRoundTrip, ProgressEveryMillionPointsOrSo)
{
	const size_t step = LoadReport::kProgressPoints, n = 2 * step + 5;
	mrpt::maps::CPointsMapXYZI map;
	map.resize(n);
	for (size_t k = 0; k < n; k++) map.setPointRGB(k, 0.001f * k, 1, 2, 0.5f, 0, 0);
	const std::string path = scratchPath("progress.pcd");
	tagmap::io::savePcdBinary(path, map);
	std::vector<size_t> heard;
	LoadReport r;
	r.progress = [&](size_t soFar) { heard.push_back(soFar); };
	EXPECT_EQ(loadPointCloud(path, &r).size(), n);
	EXPECT_EQ(heard, (std::vector<size_t>{step, 2 * step}));
}

TEST(IoRoundTrip, EmptyMap)
{
	const std::string path = scratchPath("empty.pcd");
	tagmap::io::savePcdBinary(path, mrpt::maps::CPointsMapXYZI());
	EXPECT_EQ(loadPointCloud(path).size(), 0u);
}

TEST(IoRoundTrip, OverwritesAtomicallyAndClearsTarget)
{
	const std::string path = scratchPath("again.pcd");
	mrpt::maps::CPointsMapXYZI map;
	map.insertPointRGB(1, 2, 3, 4, 0, 0);
	tagmap::io::savePcdBinary(path, map);
	mrpt::maps::CPointsMapXYZI target;
	target.insertPointRGB(9, 9, 9, 9, 0, 0);
	target.insertPointRGB(8, 8, 8, 8, 0, 0);
	tagmap::io::loadPointCloud(path, target);
	expectMapHolds(target, {{1, 2, 3, 4}});
}

TEST(IoPcd, AllEncodings)
{
	const auto pts = samplePoints(3000);  // long enough for LZF back references
	for (const std::string data : {"ascii", "binary", "binary_compressed"})
	{
		SCOPED_TRACE(data);
		LoadReport r;
		const auto map = loadPointCloud(writeFile(data + ".pcd", makePcd(pts, xyziFields(), data)), &r);
		expectMapHolds(map, pts, 1e-4f);
		EXPECT_EQ(r.format, "pcd-" + data);
	}
}

TEST(IoPcd, NumericTypes)
{
	const auto pts = samplePoints(500);
	const std::vector<std::vector<PcdField>> layouts{
		{{"x", 'F', 8}, {"y", 'F', 8}, {"z", 'F', 8}, {"intensity", 'U', 2}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'U', 1}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 8}, {"intensity", 'I', 2}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'U', 4}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'I', 4}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'U', 8}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'I', 8}},
		{{"x", 'F', 4}, {"y", 'F', 4}, {"z", 'F', 4}, {"intensity", 'F', 8}},
	};
	for (size_t k = 0; k < layouts.size(); ++k)
		for (const std::string data : {"binary", "binary_compressed", "ascii"})
		{
			SCOPED_TRACE("layout " + std::to_string(k) + " " + data);
			expectMapHolds(loadPointCloud(writeFile(std::to_string(k) + data + ".pcd", makePcd(pts, layouts[k], data))), pts, 1e-4f);
		}
}

TEST(IoPcd, SignedByteIntensityKeepsSign)
{
	auto pts = samplePoints(4);
	pts[0].i = -5;
	pts[1].i = 100;
	pts[2].i = -128;
	pts[3].i = 0;
	const std::vector<PcdField> f{{"x"}, {"y"}, {"z"}, {"intensity", 'I', 1}};
	for (const std::string data : {"binary", "binary_compressed"})
		expectMapHolds(loadPointCloud(writeFile(data + ".pcd", makePcd(pts, f, data))), pts);
}

TEST(IoPcd, FieldOrderExtraFieldsAndCounts)
{
	const auto pts = samplePoints(777);
	// Typical of real exports: padding, ring/time fields, a 33-value
	// descriptor between the coordinates, intensity first.
	const std::vector<PcdField> fields{{"intensity", 'F', 4},  {"_", 'U', 1, 3},	   {"z", 'F', 4},	 {"fpfh", 'F', 4, 33},
									   {"ring", 'U', 2},		  {"y", 'F', 8},		  {"time", 'F', 8}, {"x", 'F', 4},
									   {"normal", 'F', 4, 3}};
	for (const std::string data : {"ascii", "binary", "binary_compressed"})
	{
		SCOPED_TRACE(data);
		expectMapHolds(loadPointCloud(writeFile(data + ".pcd", makePcd(pts, fields, data))), pts, 1e-4f);
	}
}

TEST(IoPcd, IntensityFieldNames)
{
	const auto pts = samplePoints(20);
	for (const std::string name : {"reflectivity", "i"})
	{
		SCOPED_TRACE(name);
		LoadReport r;
		const auto map = loadPointCloud(
			writeFile(name + ".pcd", makePcd(pts, {{"x"}, {"y"}, {"z"}, {name, 'U', 2}}, "binary", name)), &r);
		expectMapHolds(map, pts);
		EXPECT_EQ(r.intensityField, name);
	}
}

TEST(IoPcd, OrganizedCloudSkipsNaN)
{
	auto pts = samplePoints(8 * 16);
	const float nan = std::numeric_limits<float>::quiet_NaN();
	pts[5].x = pts[6].y = pts[7].z = nan;
	pts[9].i = std::numeric_limits<float>::infinity();
	std::vector<Pt> finite;
	for (size_t k = 0; k < pts.size(); ++k)
		if (k < 5 || k > 9 || k == 8) finite.push_back(pts[k]);
	for (const std::string data : {"ascii", "binary", "binary_compressed"})
	{
		SCOPED_TRACE(data);
		LoadReport r;
		const auto map = loadPointCloud(writeFile(data + ".pcd", makePcd(pts, xyziFields(), data, "intensity", 8, 16)), &r);
		expectMapHolds(map, finite, 1e-4f);
		EXPECT_EQ(r.pointsRead, 128u);
		EXPECT_EQ(r.pointsKept, 124u);
		EXPECT_EQ(r.nonFiniteSkipped, 4u);
	}
}

TEST(IoPcd, WindowsLineEndingsInHeader)
{
	const auto pts = samplePoints(10);
	std::string pcd = makePcd(pts, xyziFields(), "binary");
	const size_t dataEnd = pcd.find("DATA binary\n") + 12;
	std::string header = pcd.substr(0, dataEnd), crlf;
	for (char c : header) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
	expectMapHolds(loadPointCloud(writeFile("crlf.pcd", crlf + pcd.substr(dataEnd))), pts);
}

TEST(IoLzf, DecodesOverlappingBackReference)
{
	// literal "ab", then a reference of length 8 at distance 2: "abababababab"
	const uint8_t in[] = {1, 'a', 'b', (6 << 5), 1};
	uint8_t out[10];
	tagmap::io::lzfDecompress(in, sizeof in, out, sizeof out);
	EXPECT_EQ(std::string(reinterpret_cast<char*>(out), 10), "ababababab");
}

TEST(IoLzf, CompressorRoundTripWithLongReferences)
{
	std::string data(5000, 'z');
	for (size_t k = 0; k < data.size(); k += 97) data[k] = static_cast<char>('a' + k % 26);
	const std::string z = lzfCompress(data);
	EXPECT_LT(z.size(), data.size() / 4);
	std::string back(data.size(), '\0');
	tagmap::io::lzfDecompress(reinterpret_cast<const uint8_t*>(z.data()), z.size(), reinterpret_cast<uint8_t*>(back.data()), back.size());
	EXPECT_EQ(back, data);
}

TEST(IoLzf, RejectsCorruptStreams)
{
	uint8_t out[16];
	const uint8_t before[] = {(1 << 5), 0};  // reference with nothing decoded yet
	EXPECT_THROW(tagmap::io::lzfDecompress(before, sizeof before, out, 16), tagmap::io::LzfError);
	const uint8_t cut[] = {5, 'a', 'b'};  // literal of 6 with 2 bytes present
	EXPECT_THROW(tagmap::io::lzfDecompress(cut, sizeof cut, out, 16), tagmap::io::LzfError);
	const uint8_t shortOut[] = {1, 'a', 'b'};  // decodes 2 of 16 bytes
	EXPECT_THROW(tagmap::io::lzfDecompress(shortOut, sizeof shortOut, out, 16), tagmap::io::LzfError);
	const uint8_t overflow[] = {0, 'a', (7 << 5), 200, 0};  // 209 bytes into 16
	EXPECT_THROW(tagmap::io::lzfDecompress(overflow, sizeof overflow, out, 16), tagmap::io::LzfError);
}

namespace
{
std::string plyHeader(const std::string& format, size_t n, const std::string& vertexProps, const std::string& before = "",
					  const std::string& after = "")
{
	return "ply\nformat " + format + " 1.0\ncomment made by test_io\n" + before + "element vertex " + std::to_string(n) + "\n" +
		   vertexProps + after + "end_header\n";
}
}  // namespace

TEST(IoPly, AsciiWithFacesAfterVertices)
{
	const auto pts = samplePoints(50);
	std::ostringstream body;
	body.precision(9);
	for (const auto& p : pts) body << p.x << ' ' << p.y << ' ' << p.z << ' ' << 3 << ' ' << p.i << "\n";
	body << "3 0 1 2\n4 1 2 3 4\n";
	const std::string text = plyHeader("ascii", pts.size(),
									   "property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty float intensity\n", "",
									   "element face 2\nproperty list uchar int vertex_indices\n") +
							 body.str();
	LoadReport r;
	expectMapHolds(loadPointCloud(writeFile("a.ply", text), &r), pts, 1e-4f);
	EXPECT_EQ(r.format, "ply-ascii");
}

TEST(IoPly, AsciiWithListBeforeVerticesAndInVertex)
{
	const auto pts = samplePoints(5);
	std::ostringstream body;
	body.precision(9);
	body << "2 9 9\n0\n";  // two "camera" records with a list
	for (const auto& p : pts) body << "2 1 1 " << p.x << ' ' << p.y << ' ' << p.z << ' ' << p.i << "\n";
	const std::string text =
		plyHeader("ascii", pts.size(), "property list uchar int tags\nproperty double x\nproperty double y\nproperty double z\nproperty ushort reflectivity\n",
				  "element camera 2\nproperty list uchar float k\n") +
		body.str();
	expectMapHolds(loadPointCloud(writeFile("b.ply", text)), pts, 1e-4f);
}

TEST(IoPly, BinaryLittleEndianSkipsOtherElements)
{
	const auto pts = samplePoints(300);
	std::string body;
	// element "camera" (fixed) then "note" (list) before the vertices
	appendRaw(body, 1.0f);
	appendRaw(body, 2.0f);
	appendRaw(body, static_cast<uint8_t>(3));
	body += "abc";
	appendRaw(body, static_cast<uint8_t>(0));
	for (const auto& p : pts)
	{
		appendRaw(body, static_cast<double>(p.x));
		appendRaw(body, static_cast<uint8_t>(1));
		appendRaw(body, p.y);
		appendRaw(body, p.z);
		appendRaw(body, static_cast<int16_t>(-1));
		appendRaw(body, p.i);
	}
	for (int f = 0; f < 2; ++f)
	{
		appendRaw(body, static_cast<uint8_t>(3));
		for (int k = 0; k < 3; ++k) appendRaw(body, static_cast<int32_t>(k));
	}
	const std::string text =
		plyHeader("binary_little_endian", pts.size(),
				  "property double x\nproperty uchar flags\nproperty float y\nproperty float z\nproperty short ring\nproperty float scalar_Intensity\n",
				  "element camera 1\nproperty float a\nproperty float b\nelement note 2\nproperty list uchar char text\n",
				  "element face 2\nproperty list uchar int vertex_indices\n") +
		body;
	LoadReport r;
	expectMapHolds(loadPointCloud(writeFile("c.ply", text), &r), pts, 1e-4f);
	EXPECT_EQ(r.format, "ply-binary");
	EXPECT_EQ(r.intensityField, "scalar_Intensity");
}

TEST(IoPly, BinaryWithListInsideVertex)
{
	const auto pts = samplePoints(40);
	std::string body;
	for (size_t k = 0; k < pts.size(); ++k)
	{
		appendRaw(body, pts[k].x);
		appendRaw(body, static_cast<uint8_t>(k % 3));
		for (size_t j = 0; j < k % 3; ++j) appendRaw(body, static_cast<uint16_t>(j));
		appendRaw(body, pts[k].y);
		appendRaw(body, pts[k].z);
		appendRaw(body, static_cast<uint8_t>(pts[k].i));
	}
	const std::string text = plyHeader("binary_little_endian", pts.size(),
									   "property float x\nproperty list uchar ushort nb\nproperty float y\nproperty float z\nproperty uchar intensity\n") +
							 body;
	expectMapHolds(loadPointCloud(writeFile("d.ply", text)), pts, 1e-4f);
}

TEST(IoKitti, ReadsFloatRecords)
{
	auto pts = samplePoints(1234);
	pts[3].z = std::numeric_limits<float>::quiet_NaN();
	std::string body;
	for (const auto& p : pts)
	{
		appendRaw(body, p.x);
		appendRaw(body, p.y);
		appendRaw(body, p.z);
		appendRaw(body, p.i / 255.0f);
	}
	auto expected = pts;
	expected.erase(expected.begin() + 3);
	for (auto& p : expected) p.i /= 255.0f;
	LoadReport r;
	expectMapHolds(loadPointCloud(writeFile("scan.bin", body), &r), expected);
	EXPECT_EQ(r.format, "kitti");
	EXPECT_EQ(r.nonFiniteSkipped, 1u);
}

TEST(IoXyzi, TextWithComments)
{
	const auto pts = samplePoints(30);
	std::ostringstream t;
	t.precision(9);
	t << "# exported by hand\n\n";
	for (const auto& p : pts) t << p.x << "\t" << p.y << " " << p.z << "  " << p.i << "   # trailing\r\n";
	for (const std::string ext : {".xyzi", ".txt", ".XYZ"})
	{
		SCOPED_TRACE(ext);
		LoadReport r;
		expectMapHolds(loadPointCloud(writeFile("pts" + ext, t.str()), &r), pts, 1e-4f);
		EXPECT_EQ(r.format, "xyzi-text");
	}
}
