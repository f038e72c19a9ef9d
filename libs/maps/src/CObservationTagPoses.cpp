// CObservationTagPoses: contents and serialization. Text and 3D views are in
// CObservationTagPoses_view.cpp.
#include "tagmap/obs/CObservationTagPoses.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/matrix_serialization.h>
#include <mrpt/core/initializer.h>
#include <mrpt/serialization/CArchive.h>

#include "tagmap/maps/register_classes.h"
#include "tagmap/maps/tag_detection_archive.h"

IMPLEMENTS_SERIALIZABLE(CObservationTagPoses, mrpt::obs::CObservation, tagmap::obs)

// Linking the observation class is enough to read rawlogs that hold it.
MRPT_INITIALIZER(tagmap_register_classes_with_CObservationTagPoses) { tagmap::maps::registerClasses(); }

namespace tagmap::obs
{
const TagDetection* CObservationTagPoses::find(const std::string& family, int id) const
{
	for (const auto& t : tags)
		if (t.family == family && t.id == id) return &t;
	return nullptr;
}

// ---- serialization ---------------------------------------------------------
// Version 1: label, stamp, sensor pose, tags (tag_detection_archive.h, with
// its own version byte; corners stored as detected).
// Version 0 (tagmap 0.1): label, stamp, sensor pose, then per tag: family,
// id, size, pose (CPose3D), covariance (6x6), points used, decode margin,
// pattern fit, mirrored; corners recomputed from pose and size.
uint8_t CObservationTagPoses::serializeGetVersion() const { return 1; }

void CObservationTagPoses::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << sensorLabel << timestamp << sensorPose;
	maps::writeTagDetections(out, tags);
}

namespace
{
TagDetection readVersion0Tag(mrpt::serialization::CArchive& in)
{
	TagDetection t;
	int32_t id = 0, pointsUsed = 0;
	mrpt::poses::CPose3D pose;
	mrpt::math::CMatrixDouble66 cov;
	in >> t.family >> id >> t.size >> pose >> cov >> pointsUsed >> t.decodeMargin >> t.patternFit >> t.mirrored;
	t.id = id;
	t.pointsUsed = pointsUsed;
	t.pose.matrix() = pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
	t.covariance = cov.asEigen();
	t.corners = cornersFromPose(t.pose, t.size);
	return t;
}
}  // namespace

void CObservationTagPoses::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	in >> sensorLabel >> timestamp >> sensorPose;
	if (version == 1)
	{
		tags = maps::readTagDetections(in);
		return;
	}
	uint32_t n = 0;
	in >> n;
	tags.clear();
	for (uint32_t i = 0; i < n; i++) tags.push_back(readVersion0Tag(in));
}

}  // namespace tagmap::obs
