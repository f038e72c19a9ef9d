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
	// A Gaussian model whose std grows with each step's distance and turn, as
	// the simulator's drift does. Not Thrun's: MRPT 2.5.8 stores a Thrun-model
	// action as a set of samples, and its particle filters' standard proposal
	// then gives every particle the same increment (stock pf-localization on
	// such a rawlog: particle spread 1e-11 after the first step, then dead
	// reckoning; docs/MRPT.md). tagmap localize re-derives its own action.
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
	m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	// Units as MRPT's own defaults write them (a2, a3 per radian / in radians).
	m.gaussianModel.a1 = 0.05;  // translation std per metre travelled
	m.gaussianModel.a2 = mrpt::RAD2DEG(0.001);  // translation std per turn
	m.gaussianModel.a3 = mrpt::DEG2RAD(2.0);  // heading std per metre travelled
	m.gaussianModel.a4 = 0.05;  // heading std per turn
	m.gaussianModel.minStdXY = 0.01;
	m.gaussianModel.minStdPHI = mrpt::DEG2RAD(0.3);
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
		// The carrier (robot base) moves; the sensor rides on it at fd.mount.
		const mrpt::poses::CPose2D robot = planar(fd.truePose * fd.mount.inverse());
		const mrpt::poses::CPose2D odometry = planar(fd.driftedPose * fd.mount.inverse());

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
