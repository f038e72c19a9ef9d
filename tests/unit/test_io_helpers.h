// Test-side writers for the formats tagmap_io reads: every file a test loads
// is produced here, byte by byte, independently of the library.
#pragma once

#include <gtest/gtest.h>
#include <mrpt/maps/CPointsMapXYZI.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "tagmap/errors.h"
#include "tagmap/io/point_cloud_io.h"

namespace iotest
{
struct Pt
{
	float x, y, z, i;
};

/** Deterministic, not-too-regular points; intensities are small integers so
 *  they survive every integer type. */
inline std::vector<Pt> samplePoints(size_t n)
{
	std::vector<Pt> pts(n);
	for (size_t k = 0; k < n; ++k)
		pts[k] = Pt{0.25f * static_cast<float>(k) - 3.0f, std::sin(0.1f * static_cast<float>(k)) * 10.0f,
					1.5f + 0.125f * static_cast<float>(k % 7), static_cast<float>((k * 37) % 200)};
	return pts;
}

inline std::string scratchPath(const std::string& name)
{
	const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
	const std::filesystem::path dir = std::filesystem::path(TAGMAP_BINARY_DIR) / "test_io_scratch";
	std::filesystem::create_directories(dir);
	return (dir / (std::string(info->test_suite_name()) + "_" + info->name() + "_" + name)).string();
}

inline std::string writeFile(const std::string& name, const std::string& bytes)
{
	const std::string path = scratchPath(name);
	std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
	return path;
}

template <typename T>
void appendRaw(std::string& s, T v)
{
	char b[sizeof(T)];
	std::memcpy(b, &v, sizeof(T));
	s.append(b, sizeof(T));
}

/** Appends `v` encoded as a PCD TYPE/SIZE ('F', 'U', 'I'). */
inline void appendTyped(std::string& s, char type, int size, double v)
{
	if (type == 'F' && size == 4) return appendRaw(s, static_cast<float>(v));
	if (type == 'F' && size == 8) return appendRaw(s, v);
	if (type == 'U' && size == 1) return appendRaw(s, static_cast<uint8_t>(v));
	if (type == 'U' && size == 2) return appendRaw(s, static_cast<uint16_t>(v));
	if (type == 'U' && size == 4) return appendRaw(s, static_cast<uint32_t>(v));
	if (type == 'U' && size == 8) return appendRaw(s, static_cast<uint64_t>(v));
	if (type == 'I' && size == 1) return appendRaw(s, static_cast<int8_t>(v));
	if (type == 'I' && size == 2) return appendRaw(s, static_cast<int16_t>(v));
	if (type == 'I' && size == 4) return appendRaw(s, static_cast<int32_t>(v));
	if (type == 'I' && size == 8) return appendRaw(s, static_cast<int64_t>(v));
	ADD_FAILURE() << "bad test type " << type << size;
}

/** A small greedy LZF compressor (hash of 3 bytes, back references up to
 *  8 KiB away and 264 long), enough to produce real back references and
 *  overlapping copies for the decoder. */
inline std::string lzfCompress(const std::string& in)
{
	std::string out;
	std::string literal;
	auto flushLiteral = [&] {
		for (size_t k = 0; k < literal.size(); k += 32)
		{
			const size_t n = std::min<size_t>(32, literal.size() - k);
			out.push_back(static_cast<char>(n - 1));
			out.append(literal, k, n);
		}
		literal.clear();
	};
	std::unordered_map<uint32_t, size_t> last;
	size_t p = 0;
	while (p < in.size())
	{
		size_t bestLen = 0, bestDist = 0;
		if (p + 3 <= in.size())
		{
			const uint32_t key = static_cast<uint8_t>(in[p]) | static_cast<uint8_t>(in[p + 1]) << 8 | static_cast<uint32_t>(static_cast<uint8_t>(in[p + 2])) << 16;
			const auto it = last.find(key);
			if (it != last.end() && p - it->second <= 8192)
			{
				size_t len = 0;
				while (p + len < in.size() && len < 264 && in[it->second + len] == in[p + len]) ++len;
				if (len >= 3) bestLen = len, bestDist = p - it->second;
			}
			last[key] = p;
		}
		if (bestLen == 0)
		{
			literal.push_back(in[p++]);
			continue;
		}
		flushLiteral();
		const size_t len = bestLen - 2, off = bestDist - 1;
		if (len < 7) out.push_back(static_cast<char>((len << 5) | (off >> 8)));
		else
		{
			out.push_back(static_cast<char>((7 << 5) | (off >> 8)));
			out.push_back(static_cast<char>(len - 7));
		}
		out.push_back(static_cast<char>(off & 0xff));
		p += bestLen;
	}
	flushLiteral();
	return out;
}

struct PcdField
{
	std::string name;
	char type = 'F';
	int size = 4;
	int count = 1;
};

/** Builds a PCD file holding `pts` in the given fields; fields that are
 *  not x/y/z or the intensity name get filler values. */
inline std::string makePcd(const std::vector<Pt>& pts, const std::vector<PcdField>& fields, const std::string& data,
						   const std::string& intensityName = "intensity", size_t width = 0, size_t height = 1)
{
	if (width == 0) width = pts.size() / height;
	std::ostringstream h;
	h << "# .PCD v0.7 - written by test_io\nVERSION 0.7\nFIELDS";
	for (const auto& f : fields) h << ' ' << f.name;
	h << "\nSIZE";
	for (const auto& f : fields) h << ' ' << f.size;
	h << "\nTYPE";
	for (const auto& f : fields) h << ' ' << f.type;
	h << "\nCOUNT";
	for (const auto& f : fields) h << ' ' << f.count;
	h << "\nWIDTH " << width << "\nHEIGHT " << height << "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << pts.size() << "\nDATA " << data << "\n";
	auto valueOf = [&](const Pt& p, const PcdField& f, int c) -> double {
		if (f.name == "x") return p.x;
		if (f.name == "y") return p.y;
		if (f.name == "z") return p.z;
		if (f.name == intensityName) return p.i;
		return 7 + c;
	};
	std::string body;
	if (data == "ascii")
	{
		std::ostringstream a;
		a.precision(9);
		for (const auto& p : pts)
		{
			for (size_t k = 0; k < fields.size(); ++k)
				for (int c = 0; c < fields[k].count; ++c) a << (k + c ? " " : "") << valueOf(p, fields[k], c);
			a << "\n";
		}
		body = a.str();
	}
	else if (data == "binary")
	{
		for (const auto& p : pts)
			for (const auto& f : fields)
				for (int c = 0; c < f.count; ++c) appendTyped(body, f.type, f.size, valueOf(p, f, c));
	}
	else  // binary_compressed: field by field
	{
		std::string soa;
		for (const auto& f : fields)
			for (const auto& p : pts)
				for (int c = 0; c < f.count; ++c) appendTyped(soa, f.type, f.size, valueOf(p, f, c));
		const std::string z = lzfCompress(soa);
		appendRaw(body, static_cast<uint32_t>(z.size()));
		appendRaw(body, static_cast<uint32_t>(soa.size()));
		body += z;
	}
	return h.str() + body;
}

inline std::vector<PcdField> xyziFields() { return {{"x"}, {"y"}, {"z"}, {"intensity"}}; }

inline void expectMapHolds(const mrpt::maps::CPointsMapXYZI& map, const std::vector<Pt>& pts, float tol = 1e-5f)
{
	ASSERT_EQ(map.size(), pts.size());
	for (size_t k = 0; k < pts.size(); ++k)
	{
		float x, y, z;
		map.getPoint(k, x, y, z);
		ASSERT_NEAR(x, pts[k].x, tol) << "point " << k;
		ASSERT_NEAR(y, pts[k].y, tol) << "point " << k;
		ASSERT_NEAR(z, pts[k].z, tol) << "point " << k;
		ASSERT_NEAR(map.getPointIntensity_fast(k), pts[k].i, tol) << "point " << k;
	}
}

/** Loading `path` must throw InputError with one line naming the file and
 *  containing `fragment`. */
inline void expectInputError(const std::string& path, const std::string& fragment)
{
	mrpt::maps::CPointsMapXYZI map;
	try
	{
		tagmap::io::loadPointCloud(path, map);
		ADD_FAILURE() << "no error for " << path;
	}
	catch (const tagmap::InputError& e)
	{
		const std::string msg = e.what();
		EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
		EXPECT_NE(msg.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << msg;
		EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
		EXPECT_EQ(map.size(), 0u);
	}
}

}  // namespace iotest
