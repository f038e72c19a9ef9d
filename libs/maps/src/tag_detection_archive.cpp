#include "tagmap/maps/tag_detection_archive.h"

#include <mrpt/core/exceptions.h>

namespace tagmap::maps
{
void writeTagDetection(mrpt::serialization::CArchive& out, const TagDetection& t)
{
	out << t.family << static_cast<int32_t>(t.id) << t.size;
	for (const auto& c : t.corners) out << c.x() << c.y() << c.z();
	const Eigen::Matrix4d T = t.pose.matrix();
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 4; c++) out << T(r, c);
	for (int r = 0; r < 6; r++)
		for (int c = 0; c < 6; c++) out << t.covariance(r, c);
	out << static_cast<int32_t>(t.pointsUsed) << t.decodeMargin << t.patternFit << t.mirrored;
}

TagDetection readTagDetection(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version != 0) THROW_EXCEPTION_FMT("unknown TagDetection archive version %u", unsigned(version));
	TagDetection t;
	int32_t id = 0, pointsUsed = 0;
	in >> t.family >> id >> t.size;
	t.id = id;
	for (auto& c : t.corners) in >> c.x() >> c.y() >> c.z();
	Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 4; c++) in >> T(r, c);
	t.pose.matrix() = T;
	for (int r = 0; r < 6; r++)
		for (int c = 0; c < 6; c++) in >> t.covariance(r, c);
	in >> pointsUsed >> t.decodeMargin >> t.patternFit >> t.mirrored;
	t.pointsUsed = pointsUsed;
	return t;
}

void writeTagDetections(mrpt::serialization::CArchive& out, const std::vector<TagDetection>& tags)
{
	out << kTagDetectionArchiveVersion << static_cast<uint32_t>(tags.size());
	for (const auto& t : tags) writeTagDetection(out, t);
}

std::vector<TagDetection> readTagDetections(mrpt::serialization::CArchive& in)
{
	uint8_t version = 0;
	uint32_t n = 0;
	in >> version >> n;
	std::vector<TagDetection> tags;  // no reserve(n): a corrupt count must not allocate first
	for (uint32_t i = 0; i < n; i++) tags.push_back(readTagDetection(in, version));
	return tags;
}

}  // namespace tagmap::maps
