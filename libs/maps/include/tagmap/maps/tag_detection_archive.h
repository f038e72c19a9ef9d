// TagDetection in MRPT archives: the one layout CTagMap and
// CObservationTagPoses both store their tags in, versioned on its own so the
// two classes cannot drift apart again.
//
// Layout version 0: family, id (int32), size, corners (4 x xyz), T_G_tag
// (rows 0-2 of the 4x4 matrix), covariance (6x6, row-major), pointsUsed
// (int32), decodeMargin, patternFit, mirrored. Every double is written as it
// is, so a tag reads back bit-identical. A list is a version byte, a uint32
// count and the tags. Bump kTagDetectionArchiveVersion and keep reading the
// old versions when the layout changes.
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <vector>

#include "tagmap/tag_detection.h"

namespace tagmap::maps
{
constexpr uint8_t kTagDetectionArchiveVersion = 0;

/** One tag, without a version byte (for containers that store their own). */
void writeTagDetection(mrpt::serialization::CArchive& out, const TagDetection& t);
TagDetection readTagDetection(mrpt::serialization::CArchive& in, uint8_t version);

/** A list: version byte, count, tags. Throws on an unknown version. */
void writeTagDetections(mrpt::serialization::CArchive& out, const std::vector<TagDetection>& tags);
std::vector<TagDetection> readTagDetections(mrpt::serialization::CArchive& in);

}  // namespace tagmap::maps
