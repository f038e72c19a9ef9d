// Beacon-ID encoding: round trip, no collisions across families, and every
// supported family has a stable index.
#include <gtest/gtest.h>

#include <set>

#include "tagmap/mrpt/beacon_id.h"
#include "tagmap/tag_family.h"

using namespace tagmap;
using namespace tagmap::mrpt_bridge;

TEST(MrptBeaconId, EverySupportedFamilyHasAnIndex)
{
	for (const auto& f : supportedFamilies()) EXPECT_NO_THROW(familyIndex(f.name)) << f.name;
}

TEST(MrptBeaconId, RoundTripAndCollisionFree)
{
	std::set<int64_t> seen;
	for (const auto& f : supportedFamilies())
		for (int id : {0, 1, f.idCount / 2, f.idCount - 1})
		{
			const int64_t b = encodeBeaconId(f.name, id);
			// Only the same marker (nested ArUco) may share an ID.
			if (markerFamily(f.name, id) == f.name)
			{
				EXPECT_TRUE(seen.insert(b).second) << f.name << " #" << id << " collides";
			}
			EXPECT_LE(b, std::numeric_limits<int32_t>::max());  // CLandmarksMap ini reads IDs with read_int
			const auto d = decodeBeaconId(b);
			EXPECT_EQ(d.family, markerFamily(f.name, id));
			EXPECT_EQ(d.id, id);
		}
}

TEST(MrptBeaconId, NestedArucoDictionariesGiveOneBeaconPerMarker)
{
	// The same printed marker, named after the dictionary a user asked for.
	EXPECT_EQ(encodeBeaconId("aruco_6x6_250", 3), encodeBeaconId("aruco_6x6_50", 3));
	EXPECT_EQ(encodeBeaconId("aruco_6x6_1000", 3), encodeBeaconId("aruco_6x6_50", 3));
	EXPECT_EQ(encodeBeaconId("aruco_6x6_1000", 120), encodeBeaconId("aruco_6x6_250", 120));
	EXPECT_EQ(decodeBeaconId(encodeBeaconId("aruco_6x6_1000", 120)).family, "aruco_6x6_250");
	// Different bit sizes and aruco_original are different markers.
	EXPECT_NE(encodeBeaconId("aruco_5x5_50", 3), encodeBeaconId("aruco_6x6_50", 3));
	EXPECT_NE(encodeBeaconId("aruco_original", 3), encodeBeaconId("aruco_6x6_50", 3));
}

TEST(MrptBeaconId, StrideExceedsEveryFamily)
{
	for (const auto& f : supportedFamilies()) EXPECT_LT(f.idCount, kBeaconIdStride) << f.name;
}

TEST(MrptBeaconId, IndicesArePublishedValues)
{
	// These numbers are in docs/MRPT.md and in users' map files: never change them.
	EXPECT_EQ(encodeBeaconId("tag36h11", 3), 100003);
	EXPECT_EQ(encodeBeaconId("aruco_4x4_50", 3), 2100003);
}

TEST(MrptBeaconId, RejectsInvalid)
{
	EXPECT_THROW(encodeBeaconId("tag36h11", -1), std::invalid_argument);
	EXPECT_THROW(encodeBeaconId("tag36h11", int(kBeaconIdStride)), std::invalid_argument);
	EXPECT_THROW(encodeBeaconId("nope", 1), std::invalid_argument);
	EXPECT_THROW(encodeBeaconId("aruco_6x6_50", 50), std::invalid_argument);
	EXPECT_THROW(decodeBeaconId(42), std::invalid_argument);
	EXPECT_THROW(decodeBeaconId(99 * kBeaconIdStride + 1), std::invalid_argument);
}
