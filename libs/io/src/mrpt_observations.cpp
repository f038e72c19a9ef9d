#include "tagmap/io/mrpt_observations.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include "reader_common.h"

namespace tagmap::io
{
namespace
{
using detail::MapFiller;

/** robotPose (+) sensorPose as plain numbers, so the per-point transform
 *  stays inline instead of a CPose3D call per point. */
class RigidTransform
{
   public:
	explicit RigidTransform(const mrpt::poses::CPose3D& pose)
	{
		const auto& R = pose.getRotationMatrix();
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 3; ++c) R_[r][c] = R(r, c);
		t_[0] = pose.x();
		t_[1] = pose.y();
		t_[2] = pose.z();
	}

	void add(float x, float y, float z, float intensity, MapFiller& fill) const
	{
		double g[3];
		for (int r = 0; r < 3; ++r) g[r] = t_[r] + R_[r][0] * x + R_[r][1] * y + R_[r][2] * z;
		fill.add(g[0], g[1], g[2], intensity);
	}

   private:
	double R_[3][3];
	double t_[3];
};

bool appendPointCloud(const mrpt::obs::CObservationPointCloud& o, const mrpt::poses::CPose3D& robotPose, mrpt::maps::CPointsMapXYZI& out,
					  LoadReport& report)
{
	o.load();  // externally stored clouds are read on demand
	const auto* cloud = dynamic_cast<const mrpt::maps::CPointsMapXYZI*>(o.pointcloud.get());
	if (!cloud) return false;
	const RigidTransform T(robotPose + o.sensorPose);
	const auto& xs = cloud->getPointsBufferRef_x();
	const auto& ys = cloud->getPointsBufferRef_y();
	const auto& zs = cloud->getPointsBufferRef_z();
	const auto& is = cloud->getPointsBufferRef_intensity();
	MapFiller fill(out, report);
	fill.expect(xs.size());
	for (size_t k = 0; k < xs.size(); ++k) T.add(xs[k], ys[k], zs[k], is[k], fill);
	fill.finish();
	return true;
}

bool appendVelodyne(const mrpt::obs::CObservationVelodyneScan& o, const mrpt::poses::CPose3D& robotPose, mrpt::maps::CPointsMapXYZI& out,
					LoadReport& report)
{
	const mrpt::obs::CObservationVelodyneScan::TPointCloud* pc = &o.point_cloud;
	// Recorded scans usually keep only the raw packets; decode a copy rather
	// than touching the caller's observation.
	mrpt::obs::CObservationVelodyneScan decoded;
	if (pc->size() == 0 && !o.scan_packets.empty())
	{
		decoded = o;
		decoded.generatePointCloud();
		pc = &decoded.point_cloud;
	}
	if (pc->intensity.size() != pc->size() || pc->y.size() != pc->size() || pc->z.size() != pc->size()) return false;
	const RigidTransform T(robotPose + o.sensorPose);
	MapFiller fill(out, report);
	fill.expect(pc->size());
	for (size_t k = 0; k < pc->size(); ++k) T.add(pc->x[k], pc->y[k], pc->z[k], pc->intensity[k], fill);
	fill.finish();
	return true;
}

bool append3DRangeScan(const mrpt::obs::CObservation3DRangeScan& o, const mrpt::poses::CPose3D& robotPose, mrpt::maps::CPointsMapXYZI& out,
					   LoadReport& report)
{
	o.load();
	if (!o.hasIntensityImage || !(o.hasPoints3D || o.hasRangeImage)) return false;
	// MRPT knows the camera model, so it unprojects (into the sensor frame);
	// but its loadFromRangeScan() leaves XYZI intensity at 1, so the
	// intensity image is sampled here at each point's pixel.
	const mrpt::obs::CObservation3DRangeScan* src = &o;
	mrpt::obs::CObservation3DRangeScan unprojected;
	if (!o.hasPoints3D)
	{
		unprojected = o;
		unprojected.unprojectInto(unprojected);
		src = &unprojected;
	}
	const size_t n = src->points3D_x.size();
	if (src->points3D_idxs_x.size() != n || src->points3D_idxs_y.size() != n) return false;
	const mrpt::img::CImage gray(src->intensityImage, mrpt::img::FAST_REF_OR_CONVERT_TO_GRAY);
	const size_t w = gray.getWidth(), h = gray.getHeight();
	const RigidTransform T(robotPose + src->sensorPose);
	MapFiller fill(out, report);
	fill.expect(n);
	for (size_t k = 0; k < n; ++k)
	{
		const size_t c = src->points3D_idxs_x[k], r = src->points3D_idxs_y[k];
		const float intensity = c < w && r < h ? gray.at<uint8_t>(static_cast<unsigned>(c), static_cast<unsigned>(r)) : std::nanf("");
		T.add(src->points3D_x[k], src->points3D_y[k], src->points3D_z[k], intensity, fill);
	}
	fill.finish();
	return true;
}

}  // namespace

bool appendObservationToMap(const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& robotPose, mrpt::maps::CPointsMapXYZI& out,
							LoadReport& report)
{
	bool used = false;
	if (const auto* pc = dynamic_cast<const mrpt::obs::CObservationPointCloud*>(&obs)) used = appendPointCloud(*pc, robotPose, out, report);
	else if (const auto* velo = dynamic_cast<const mrpt::obs::CObservationVelodyneScan*>(&obs))
		used = appendVelodyne(*velo, robotPose, out, report);
	else if (const auto* rgbd = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs))
		used = append3DRangeScan(*rgbd, robotPose, out, report);
	++(used ? report.observationsUsed : report.observationsSkipped);
	if (used)
	{
		mrpt::poses::CPose3D sensorPose;
		obs.getSensorPose(sensorPose);
		const mrpt::poses::CPose3D at = robotPose + sensorPose;
		report.viewpoints.emplace_back(at.x(), at.y(), at.z());
	}
	return used;
}

}  // namespace tagmap::io
