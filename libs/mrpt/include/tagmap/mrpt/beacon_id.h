// Beacon IDs for tags. MRPT beacon maps key landmarks by one integer, but a
// tag is only unique as (family, id): tag36h11 #3 and aruco_4x4_50 #3 are
// different markers. Every place that hands tags to MRPT (CLandmarksMap,
// the [MetricMap] ini, CTagMap likelihoods) goes through these functions so
// the mapping is the same everywhere.
//
//   beaconID = familyIndex * kBeaconIdStride + id
//
// familyIndex comes from a fixed table (docs/MRPT.md): it never depends on
// the order of supportedFamilies(), so IDs stay valid across versions. New
// families get new indices; existing indices are never reused. Index 0 is
// never assigned, so beacon IDs below kBeaconIdStride are left for
// hand-numbered beacons. The stride exceeds the largest family (tagCircle49h12,
// 65535 ids), so IDs never collide, and the largest ID fits a signed int
// (CLandmarksMap's ini reader parses IDs with read_int).
//
// A beacon is a printed marker, not a reading of it. OpenCV's nested ArUco
// dictionaries hold the same first codes (DICT_6X6_50 is the first 50 of
// DICT_6X6_250), so a tag is named aruco_6x6_50 or aruco_6x6_250 depending
// on the --family asked for; both get the ID of markerFamily() (the smallest
// dictionary holding the id), so a map made without --family and a rawlog
// observed with one agree.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tagmap::mrpt_bridge
{
constexpr int64_t kBeaconIdStride = 100000;

/** Stable index of a family (see the table in docs/MRPT.md); throws
 *  std::invalid_argument for a family without one. */
int familyIndex(const std::string& family);

/** The family of a stable index; throws std::invalid_argument if unassigned. */
const std::string& familyOfIndex(int index);

/** Every (family, index) pair of the table, in index order. */
const std::vector<std::pair<std::string, int>>& familyIndexTable();

/** familyIndex(markerFamily(family, id)) * kBeaconIdStride + id; throws
 *  std::invalid_argument for an unknown family or an id it does not have. */
int64_t encodeBeaconId(const std::string& family, int id);

struct DecodedBeaconId
{
	std::string family;
	int id = -1;
};

/** Inverse of encodeBeaconId (the family is markerFamily()'s name; IDs
 *  of the larger nested dictionaries' indices decode to those); throws std::invalid_argument for an ID no tag
 *  can have. */
DecodedBeaconId decodeBeaconId(int64_t beaconId);

}  // namespace tagmap::mrpt_bridge
