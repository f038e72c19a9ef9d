// LAS 1.0-1.4: files written by saveLas() and files built here byte by
// byte from the ASPRS layout (VLRs, EVLRs, legacy and 64-bit counts) read
// back in double; every malformed header is one InputError line.
#include "test_io_helpers.h"

using namespace iotest;

namespace
{
/** A LAS file of `pts` built here, independently of the library: version
 *  1.minor, one VLR of `vlrBytes` payload, `evlr` bytes of EVLR after the
 *  points, scale 0.001 around `offset`. */
std::string makeLas(const std::vector<Pt>& pts, int minor, int format, size_t recordLength, const double (&offset)[3],
					size_t vlrBytes = 0, size_t evlr = 0, bool legacyCount = true)
{
	const size_t headerSize = minor >= 4 ? 375 : minor == 3 ? 235 : 227;
	std::string h(headerSize, '\0');
	auto put = [&](size_t at, auto v) { std::memcpy(&h[at], &v, sizeof(v)); };
	std::memcpy(&h[0], "LASF", 4);
	put(24, uint8_t{1});
	put(25, static_cast<uint8_t>(minor));
	put(94, static_cast<uint16_t>(headerSize));
	const size_t vlrTotal = vlrBytes ? 54 + vlrBytes : 0;
	put(96, static_cast<uint32_t>(headerSize + vlrTotal));
	put(100, static_cast<uint32_t>(vlrBytes ? 1 : 0));
	put(104, static_cast<uint8_t>(format));
	put(105, static_cast<uint16_t>(recordLength));
	put(107, static_cast<uint32_t>(legacyCount ? pts.size() : 0));
	for (int a = 0; a < 3; ++a)
	{
		put(131 + 8 * a, 0.001);
		put(155 + 8 * a, offset[a]);
	}
	if (minor >= 4) put(247, static_cast<uint64_t>(pts.size()));
	std::string s = h;
	if (vlrBytes) s += std::string(54, 'v') + std::string(vlrBytes, 'V');
	for (const Pt& p : pts)
	{
		std::string rec(recordLength, '\x5a');
		const int32_t xyz[3] = {static_cast<int32_t>(std::lround(p.x / 0.001)), static_cast<int32_t>(std::lround(p.y / 0.001)),
								static_cast<int32_t>(std::lround(p.z / 0.001))};
		std::memcpy(&rec[0], xyz, 12);
		const uint16_t i = static_cast<uint16_t>(p.i);
		std::memcpy(&rec[12], &i, 2);
		s += rec;
	}
	if (evlr && minor >= 4)
	{
		const uint64_t at = s.size();
		std::memcpy(&s[235], &at, 8);
		const uint32_t n = 1;
		std::memcpy(&s[243], &n, 4);
		s += std::string(evlr, 'E');
	}
	return s;
}

void expectPoints(const mrpt::maps::CPointsMapXYZI& m, const std::vector<Pt>& pts, const Eigen::Vector3d& shift,
				  const Eigen::Vector3d& origin, double tol)
{
	ASSERT_EQ(m.size(), pts.size());
	for (size_t k = 0; k < pts.size(); ++k)
	{
		float x, y, z;
		m.getPoint(k, x, y, z);
		EXPECT_NEAR(x + origin.x(), pts[k].x + shift.x(), tol) << k;
		EXPECT_NEAR(y + origin.y(), pts[k].y + shift.y(), tol) << k;
		EXPECT_NEAR(z + origin.z(), pts[k].z + shift.z(), tol) << k;
	}
}

mrpt::maps::CPointsMapXYZI toMap(const std::vector<Pt>& pts)
{
	mrpt::maps::CPointsMapXYZI m;
	for (const Pt& p : pts)
	{
		m.insertPointFast(p.x, p.y, p.z);
		m.setPointIntensity(m.size() - 1, p.i);
	}
	m.mark_as_modified();
	return m;
}
}  // namespace

TEST(IoLas, RoundTripEveryPointFormat)
{
	const auto pts = samplePoints(500);
	const mrpt::maps::CPointsMapXYZI map = toMap(pts);
	for (int format = 0; format <= 10; ++format)
	{
		const std::string path = scratchPath("f" + std::to_string(format) + ".las");
		tagmap::io::LasWriteParams p;
		p.pointFormat = format;
		tagmap::io::saveLas(path, map, p);
		tagmap::io::LoadReport r;
		const auto back = tagmap::io::loadPointCloud(path, &r);
		EXPECT_EQ(r.format, "las-1." + std::to_string(format <= 3 ? 2 : 4) + "-format-" + std::to_string(format));
		EXPECT_EQ(r.origin, Eigen::Vector3d::Zero());
		expectPoints(back, pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0005 + 1e-6);
		// Intensity is stretched to 16 bits: 0..199 -> 0..65535, order kept.
		const float scale = 65535.0f / 199.0f;
		for (size_t k = 0; k < pts.size(); ++k)
			EXPECT_NEAR(back.getPointIntensity(k), pts[k].i * scale, 0.51f) << "format " << format << " point " << k;
	}
}

TEST(IoLas, GeoreferencedShiftKeepsMillimetres)
{
	const auto pts = samplePoints(2000);
	const Eigen::Vector3d shift(512345, 5123456, 187);
	for (int format : {0, 1, 6, 7})
	{
		const std::string path = scratchPath("utm" + std::to_string(format) + ".las");
		tagmap::io::LasWriteParams p;
		p.pointFormat = format;
		p.shift = shift;
		tagmap::io::saveLas(path, toMap(pts), p);
		tagmap::io::LoadReport r;
		const auto back = tagmap::io::loadPointCloud(path, &r);
		// Whole metres near the points' median on axes far from the file's origin.
		EXPECT_EQ(r.origin.x(), std::round(r.origin.x()));
		EXPECT_NEAR(r.origin.x(), shift.x() + 250, 10);
		EXPECT_NEAR(r.origin.y(), shift.y(), 100);
		EXPECT_EQ(r.origin.z(), 0);  // 187 m: within 1 km, as it is
		expectPoints(back, pts, shift, r.origin, 0.0005 + 3e-5);
	}
}

TEST(IoLas, Float64PcdShiftKeepsPrecision)
{
	const auto pts = samplePoints(2000);
	const Eigen::Vector3d shift(512345, 5123456, 187);
	const std::string path = scratchPath("utm.pcd");
	tagmap::io::savePcdBinary(path, toMap(pts), shift);
	tagmap::io::LoadReport r;
	const auto back = tagmap::io::loadPointCloud(path, &r);
	expectPoints(back, pts, shift, r.origin, 2e-5);
	// An explicit origin is used as given.
	tagmap::io::LoadParams lp;
	lp.fixedOrigin = true;
	lp.origin = Eigen::Vector3d(512000, 5123000, 0);
	const auto fixed = tagmap::io::loadPointCloud(path, &r, lp);
	EXPECT_EQ(r.origin, lp.origin);
	expectPoints(fixed, pts, shift, lp.origin, 1e-4);
}

TEST(IoLas, MedianNotFirstPointsChooseTheOrigin)
{
	// The file starts with 5000 stray points 1500 km away: the origin chosen
	// from the first points is wrong, the map is read again around its median.
	std::vector<Pt> pts(5000, Pt{1.5e6f, 0, 0, 1});
	auto good = samplePoints(20000);
	for (Pt& p : good) p.x = std::fmod(p.x + 3, 100.0f);
	pts.insert(pts.end(), good.begin(), good.end());
	tagmap::io::LoadReport r;
	const auto back = tagmap::io::loadPointCloud(writeFile("first.pcd", makePcd(pts, xyziFields(), "binary")), &r);
	EXPECT_EQ(r.origin, Eigen::Vector3d::Zero());
	EXPECT_EQ(back.size(), pts.size());
}

TEST(IoLas, SentinelsDoNotBecomeTheOrigin)
{
	const std::vector<Pt> pts{{1e30f, 0, 1, 5}, {NAN, 0, 1, 5}, {0, 0, 1, 5}};
	tagmap::io::LoadReport r;
	const auto m = tagmap::io::loadPointCloud(writeFile("s.pcd", makePcd(pts, xyziFields(), "binary")), &r);
	EXPECT_EQ(r.origin, Eigen::Vector3d::Zero());
	EXPECT_EQ(m.size(), 1u);
	EXPECT_EQ(r.outOfRangeSkipped, 1u);
	EXPECT_EQ(r.nonFiniteSkipped, 1u);
}

TEST(IoLas, HandBuiltFilesWithVlrsEvlrsAndCounts)
{
	const auto pts = samplePoints(300);
	const double offset[3] = {0, 0, 0};
	for (int minor = 0; minor <= 4; ++minor)
	{
		tagmap::io::LoadReport r;
		const auto m = tagmap::io::loadPointCloud(
			writeFile("v" + std::to_string(minor) + ".las", makeLas(pts, minor, minor >= 4 ? 6 : 1, 40, offset, 17, 99)), &r);
		expectPoints(m, pts, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0005 + 1e-6);
		for (size_t k = 0; k < pts.size(); ++k) EXPECT_EQ(m.getPointIntensity(k), pts[k].i);
	}
	// LAS 1.4 formats 6-10 leave the legacy count 0: the 64-bit one counts.
	tagmap::io::LoadReport r;
	const auto m = tagmap::io::loadPointCloud(writeFile("c64.las", makeLas(pts, 4, 7, 36, offset, 0, 0, false)), &r);
	EXPECT_EQ(m.size(), pts.size());
}

TEST(IoLas, MalformedHeadersAreOneLine)
{
	const auto pts = samplePoints(50);
	const double offset[3] = {0, 0, 0};
	const std::string good = makeLas(pts, 2, 1, 28, offset);
	auto patched = [&](size_t at, auto v) {
		std::string s = good;
		std::memcpy(&s[at], &v, sizeof(v));
		return s;
	};
	expectInputError(writeFile("sig.las", "LASX" + good.substr(4)), "header: not a LAS file");
	expectInputError(writeFile("short.las", good.substr(0, 100)), "header: truncated: 100 bytes");
	expectInputError(writeFile("empty.las", ""), "empty file");
	expectInputError(writeFile("cut.las", good.substr(0, good.size() - 3)), "point count 50 is larger than the file holds (49 records");
	expectInputError(writeFile("count.las", patched(107, uint32_t{4000000000u})), "point count 4000000000 is larger than the file holds");
	expectInputError(writeFile("hsize.las", patched(94, uint16_t{100})), "bad header size 100");
	expectInputError(writeFile("hbig.las", patched(94, uint16_t{60000})), "bad header size 60000");
	expectInputError(writeFile("fmt.las", patched(104, uint8_t{11})), "unknown point data record format 11");
	expectInputError(writeFile("laz.las", patched(104, uint8_t{0x81})), "compressed (LAZ) point data is not read; decompress it first");
	expectInputError(writeFile("reclen.las", patched(105, uint16_t{10})), "point record length 10 is shorter than format 1's 28 bytes");
	expectInputError(writeFile("ver.las", patched(25, uint8_t{7})), "LAS version 1.7 is not supported");
	expectInputError(writeFile("off.las", patched(96, uint32_t{1u << 30})), "offset to point data 1073741824 is outside the file");
	expectInputError(writeFile("scale.las", patched(131, 0.0)), "bad X scale or offset");
	expectInputError(writeFile("nan.las", patched(163, std::nan(""))), "bad Y scale or offset");
	const std::string v14 = makeLas(pts, 4, 6, 30, offset, 0, 0, false);
	std::string big = v14;
	const uint64_t huge = uint64_t{1} << 60;
	std::memcpy(&big[247], &huge, 8);
	expectInputError(writeFile("c64big.las", big), "point count 1152921504606846976 is larger than the file holds");
	expectInputError(writeFile("map.laz", good), "LAZ (compressed LAS) is not read; decompress it first");
}
