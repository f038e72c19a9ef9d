// CObservationTagPoses: contents and serialization. Text and 3D views are in
// CObservationTagPoses_view.cpp.
#include "tagmap/obs/CObservationTagPoses.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/matrix_serialization.h>
#include <mrpt/core/initializer.h>
#include <mrpt/serialization/CArchive.h>

#include "tagmap/maps/register_classes.h"

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
// Version 0: label, stamp, sensor pose, then per tag: family, id, size, pose
// (CPose3D), covariance (6x6), points used, decode margin, pattern fit,
// mirrored. Corners are not stored: they follow from pose and size. Bump the
// version and keep reading old ones when the layout changes.
uint8_t CObservationTagPoses::serializeGetVersion() const { return 0; }

void CObservationTagPoses::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << sensorLabel << timestamp << sensorPose << static_cast<uint32_t>(tags.size());
	for (const TagDetection& t : tags)
	{
		out << t.family << static_cast<int32_t>(t.id) << t.size;
		out << mrpt::poses::CPose3D(mrpt::math::CMatrixDouble44(t.pose.matrix()));
		out << mrpt::math::CMatrixDouble66(t.covariance);
		out << static_cast<int32_t>(t.pointsUsed) << t.decodeMargin << t.patternFit << t.mirrored;
	}
}

void CObservationTagPoses::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	uint32_t n = 0;
	in >> sensorLabel >> timestamp >> sensorPose >> n;
	tags.assign(n, TagDetection{});
	for (TagDetection& t : tags)
	{
		int32_t id = 0, pointsUsed = 0;
		mrpt::poses::CPose3D pose;
		mrpt::math::CMatrixDouble66 cov;
		in >> t.family >> id >> t.size >> pose >> cov >> pointsUsed >> t.decodeMargin >> t.patternFit >> t.mirrored;
		t.id = id;
		t.pointsUsed = pointsUsed;
		t.pose.matrix() = pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
		t.covariance = cov.asEigen();
		t.corners = cornersFromPose(t.pose, t.size);
	}
}

}  // namespace tagmap::obs
