#include "tagmap/mrpt/beacon_id.h"

#include <stdexcept>

#include "tagmap/tag_family.h"

namespace tagmap::mrpt_bridge
{
const std::vector<std::pair<std::string, int>>& familyIndexTable()
{
	// Append only: a published index must keep meaning the same family, or
	// maps written by older versions would silently relabel their tags.
	// AprilTag families take 1..19, ArUco dictionaries 20 onwards.
	static const std::vector<std::pair<std::string, int>> table = {
		{"tag36h11", 1},		 {"tag25h9", 2},		 {"tag16h5", 3},		{"tagStandard41h12", 4},
		{"tagStandard52h13", 5}, {"tagCircle21h7", 6},	 {"tagCircle49h12", 7}, {"tagCustom48h12", 8},
		{"aruco_original", 20},	 {"aruco_4x4_50", 21},	 {"aruco_4x4_100", 22}, {"aruco_4x4_250", 23},
		{"aruco_4x4_1000", 24},	 {"aruco_5x5_50", 25},	 {"aruco_5x5_100", 26}, {"aruco_5x5_250", 27},
		{"aruco_5x5_1000", 28},	 {"aruco_6x6_50", 29},	 {"aruco_6x6_100", 30}, {"aruco_6x6_250", 31},
		{"aruco_6x6_1000", 32},	 {"aruco_7x7_50", 33},	 {"aruco_7x7_100", 34}, {"aruco_7x7_250", 35},
		{"aruco_7x7_1000", 36},
	};
	return table;
}

int familyIndex(const std::string& family)
{
	for (const auto& [name, index] : familyIndexTable())
		if (name == family) return index;
	throw std::invalid_argument("no beacon-ID family index for tag family '" + family + "'");
}

const std::string& familyOfIndex(int index)
{
	for (const auto& [name, i] : familyIndexTable())
		if (i == index) return name;
	throw std::invalid_argument("beacon-ID family index " + std::to_string(index) + " is not assigned");
}

int64_t encodeBeaconId(const std::string& family, int id)
{
	if (id < 0 || id >= kBeaconIdStride)
		throw std::invalid_argument("tag id " + std::to_string(id) + " of " + family + " does not fit a beacon ID");
	// One beacon per printed marker: aruco_6x6_250 #3 is aruco_6x6_50 #3.
	const TagFamilyInfo* info = findFamily(family);
	if (info && id >= info->idCount)
		throw std::invalid_argument(family + " has no tag id " + std::to_string(id));
	return familyIndex(markerFamily(family, id)) * kBeaconIdStride + id;
}

DecodedBeaconId decodeBeaconId(int64_t beaconId)
{
	if (beaconId < kBeaconIdStride)
		throw std::invalid_argument("beacon ID " + std::to_string(beaconId) + " does not encode a tag");
	DecodedBeaconId out;
	out.family = familyOfIndex(static_cast<int>(beaconId / kBeaconIdStride));
	out.id = static_cast<int>(beaconId % kBeaconIdStride);
	return out;
}

}  // namespace tagmap::mrpt_bridge
