#include "tagmap/sim/sim_rawlog.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <ostream>

#include "tagmap/atomic_file.h"
#include "tagmap/errors.h"
#include "tagmap/sim/sim_outputs.h"

namespace tagmap::sim
{
namespace
{
/** A wheeled robot's view of a sensor pose: its ground-plane position and heading. */
mrpt::poses::CPose2D planar(const Eigen::Isometry3d& T)
{
	const Eigen::Vector3d x = T.linear().col(0);
	return {T.translation().x(), T.translation().y(), std::atan2(x.y(), x.x())};
}

}  // namespace

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions RawlogOptions::defaultMotionModel()
{
	// Thrun's model: noise grows with the distance and turn of each step, as
	// the simulator's drift does (per sqrt metre, per sqrt second).
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
	m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
	m.thrunModel.alfa1_rot_rot = 0.05f;
	m.thrunModel.alfa2_rot_trans = static_cast<float>(mrpt::DEG2RAD(2.0));
	m.thrunModel.alfa3_trans_trans = 0.05f;
	m.thrunModel.alfa4_trans_rot = 0.001f;
	m.thrunModel.additional_std_XY = 0.01f;
	m.thrunModel.additional_std_phi = static_cast<float>(mrpt::DEG2RAD(0.3));
	return m;
}

mrpt::obs::CRawlog toRawlog(const SimulationOutput& out, const RawlogOptions& options)
{
	// The scans as the simplemap holds them (sensor frame, XYZI): one
	// conversion for both outputs.
	mrpt::maps::CSimpleMap keyframes = toSimpleMap(out);
	mrpt::obs::CRawlog log;
	mrpt::poses::CPose2D lastOdometry;
	for (size_t k = 0; k < out.frames.size(); k++)
	{
		const FrameData& fd = out.frames[k];
		const mrpt::poses::CPose2D robot = planar(fd.truePose);
		const mrpt::poses::CPose2D odometry = planar(fd.driftedPose);

		mrpt::obs::CActionRobotMovement2D move;
		move.timestamp = mrpt::Clock::fromDouble(fd.stamp);
		move.computeFromOdometry(k ? odometry - lastOdometry : mrpt::poses::CPose2D(), options.motionModel);
		mrpt::obs::CActionCollection actions;
		actions.insert(move);
		log.insert(actions);
		lastOdometry = odometry;

		// robot (+) sensorPose == the true sensor pose, exactly.
		const mrpt::poses::CPose3D sensorOnRobot =
			mrpt::poses::CPose3D(mrpt::math::CMatrixDouble44(fd.truePose.matrix())) - mrpt::poses::CPose3D(robot);
		mrpt::obs::CSensoryFrame::Ptr sf = keyframes.getAsPair(k).sf;
		for (auto& obs : *sf) obs->setSensorPose(sensorOnRobot);
		log.insert(*sf);
	}
	return log;
}

void writeSimulationRawlog(const std::string& path, const std::string& truthTumPath, const SimulationOutput& out,
						   const RawlogOptions& options)
{
	checkOutputWritable(path);
	checkOutputWritable(truthTumPath);
	const mrpt::obs::CRawlog log = toRawlog(out, options);
	writeFileAtomicallyByName(path, [&](const std::string& tmp) {
		if (!log.saveToRawLogFile(tmp)) throw InputError(tmp, "", "cannot write rawlog");
	});
	const std::string tum = tumTrajectory(out, false);
	writeFileAtomically(truthTumPath, [&](std::ostream& o) { o << tum; });
}

}  // namespace tagmap::sim
