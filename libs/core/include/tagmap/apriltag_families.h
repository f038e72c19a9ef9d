// Owning handles to libapriltag family objects and OpenCV ArUco
// dictionaries, for code that talks to the decoders directly.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/aruco.hpp>

struct apriltag_family;

namespace tagmap
{
using AprilTagFamilyPtr = std::unique_ptr<apriltag_family, void (*)(apriltag_family*)>;

/** libapriltag family names, in the order tagmap tries them. */
const std::vector<std::string>& aprilTagFamilyNames();

/** A fresh family object (each detector needs its own: the detector keeps
 *  decode tables inside it). Throws std::invalid_argument if unknown. */
AprilTagFamilyPtr createAprilTagFamily(const std::string& name);

/** The family with its decode tables for up to `bitsCorrected` corrected
 *  bits, built once and shared by every caller while any holds it (the
 *  tables are read-only during detection; tagStandard52h13 alone is over
 *  100 MB). Add it to a detector with apriltag_detector_add_family_bits
 *  (which then only registers it), and detach it before destroying that
 *  detector: zarray_clear(detector->tag_families). */
std::shared_ptr<apriltag_family> sharedAprilTagFamily(const std::string& name, int bitsCorrected);

/** Decode-table entries one family may take (16 bytes each at load 1/2:
 *  32 MB). tag36h11 with 2 corrected bits fits; the families with tens of
 *  thousands of codes would take 100-170 MB each at 1 or 2 bits, so they
 *  are read exactly by libapriltag and corrected by the soft decoder, which
 *  needs no table: their codes are 12-13 bits apart. */
constexpr unsigned long long kDecodeTableEntryBudget = 1'000'000;

/** The most bits, up to `wanted`, whose decode table for family `name`
 *  stays within kDecodeTableEntryBudget entries. */
int affordableBitsCorrected(const std::string& name, int wanted);

/** OpenCV dictionary for an "aruco_*" family name. */
cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const std::string& name);

}  // namespace tagmap
