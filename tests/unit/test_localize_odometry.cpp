// Odometry for the localizers from both rawlog formats: the same motion
// written as CActionRobotMovement2D, as CActionRobotMovement3D (actions
// format) and as absolute CObservationOdometry readings (observations-only
// format) gives the same steps; a rawlog without odometry is an InputError
// when odometry is required, zero increments when it is ignored.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <functional>

#include "tagmap/errors.h"
#include "tagmap/localize/localization_steps.h"

using namespace tagmap;
using namespace tagmap::localize;

namespace
{
const mrpt::poses::CPose3D kLidarOnRobot(0.3, 0, 1.2, 0, 0, 0);

/** The robot's odometry readings: two per scan, a curve. */
std::vector<mrpt::poses::CPose2D> readings()
{
	std::vector<mrpt::poses::CPose2D> r{mrpt::poses::CPose2D(5, -2, 1.0)};
	for (int i = 1; i < 12; i++) r.push_back(r.back() + mrpt::poses::CPose2D(0.25, 0.01 * i, 0.05 * (i % 4) - 0.04));
	return r;
}

obs::CObservationTagPoses::Ptr scanAt(double t)
{
	auto o = obs::CObservationTagPoses::Create();
	o->timestamp = mrpt::Clock::fromDouble(t);
	o->sensorPose = kLidarOnRobot;
	return o;
}

/** Saved and read back, as `tagmap localize` gets it from a file. */
mrpt::obs::CRawlog roundTrip(const mrpt::obs::CRawlog& log)
{
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << log;
	buf.Seek(0);
	mrpt::obs::CRawlog back;
	mrpt::serialization::archiveFrom(buf) >> back;
	return back;
}

/** Actions format: one action per reading-to-reading increment, each with
 *  its sensory frame (the scan with the last one before it, else empty), as
 *  the observations format below has them. */
mrpt::obs::CRawlog actionsRawlog(const std::function<mrpt::obs::CActionCollection(const mrpt::poses::CPose2D&)>& act,
								 bool alsoOdometryObservations = false)
{
	const auto r = readings();
	mrpt::obs::CRawlog log;
	for (size_t i = 1; i < r.size(); i++)
	{
		mrpt::obs::CActionCollection a = act(r[i] - r[i - 1]);
		log.insert(a);
		mrpt::obs::CSensoryFrame sf;
		if (alsoOdometryObservations)
		{
			auto odo = mrpt::obs::CObservationOdometry::Create();
			odo->odometry = r[i];
			sf.insert(odo);
		}
		if (i % 2 == 1) sf.insert(scanAt(static_cast<double>(i - 1)));
		log.insert(sf);
	}
	return roundTrip(log);
}

mrpt::obs::CActionCollection move2D(const mrpt::poses::CPose2D& d)
{
	mrpt::obs::CActionRobotMovement2D m;
	m.computeFromOdometry(d, mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
	mrpt::obs::CActionCollection a;
	a.insert(m);
	return a;
}

mrpt::obs::CActionCollection move3D(const mrpt::poses::CPose2D& d)
{
	mrpt::obs::CActionRobotMovement3D m;
	m.rawOdometryIncrementReading = mrpt::poses::CPose3D(d);
	m.poseChange.mean = mrpt::poses::CPose3D(d);
	m.poseChange.cov.setDiagonal(1e-4);
	mrpt::obs::CActionCollection a;
	a.insert(m);
	return a;
}

/** Observations format: every absolute reading, scans in between. */
mrpt::obs::CRawlog observationsRawlog(bool withOdometry = true)
{
	const auto r = readings();
	mrpt::obs::CRawlog log;
	for (size_t i = 0; i < r.size(); i++)
	{
		if (withOdometry)
		{
			auto odo = mrpt::obs::CObservationOdometry::Create();
			odo->timestamp = mrpt::Clock::fromDouble(static_cast<double>(i) - 0.5);
			odo->odometry = r[i];
			log.insert(odo);
		}
		if (i % 2 == 1) log.insert(scanAt(static_cast<double>(i - 1)));
	}
	return roundTrip(log);
}

void expectSameOdometry(const std::vector<LocalizationStep>& a, const std::vector<LocalizationStep>& b)
{
	ASSERT_EQ(a.size(), b.size());
	for (size_t k = 0; k < a.size(); k++)
	{
		EXPECT_NEAR(a[k].odometry.x(), b[k].odometry.x(), 1e-9) << "step " << k;
		EXPECT_NEAR(a[k].odometry.y(), b[k].odometry.y(), 1e-9) << "step " << k;
		EXPECT_NEAR(a[k].odometry.phi(), b[k].odometry.phi(), 1e-9) << "step " << k;
		EXPECT_EQ(a[k].sensorPose, kLidarOnRobot);
	}
}
}  // namespace

TEST(LocalizeOdometry, BothRawlogFormatsGiveTheSameSteps)
{
	const auto from2D = localizationSteps(actionsRawlog(move2D), "2d", OdometryUse::required);
	const auto from3D = localizationSteps(actionsRawlog(move3D), "3d", OdometryUse::required);
	const auto fromObs = localizationSteps(observationsRawlog(), "obs", OdometryUse::required);
	ASSERT_EQ(from2D.size(), 6u);
	// The robot moved: the steps are not all zero.
	EXPECT_GT(from2D[1].odometry.norm(), 0.4);
	expectSameOdometry(from2D, from3D);
	expectSameOdometry(from2D, fromObs);
	// Composed, the steps are the whole way from the first reading.
	mrpt::poses::CPose2D sum = readings().front();
	for (const auto& s : fromObs) sum = sum + s.odometry;
	const mrpt::poses::CPose2D last = readings().back();
	EXPECT_NEAR(sum.x(), last.x(), 1e-9);
	EXPECT_NEAR(sum.phi(), last.phi(), 1e-9);
}

TEST(LocalizeOdometry, ActionsWinOverOdometryObservations)
{
	// A rawlog holding the motion both ways must not count it twice.
	expectSameOdometry(localizationSteps(actionsRawlog(move2D, true), "both", OdometryUse::required),
					   localizationSteps(actionsRawlog(move2D), "2d", OdometryUse::required));
}

TEST(LocalizeOdometry, NoOdometryIsAnErrorUnlessIgnoredOrOptional)
{
	const mrpt::obs::CRawlog log = observationsRawlog(false);
	try
	{
		localizationSteps(log, "robot.rawlog", OdometryUse::required);
		FAIL() << "no odometry must be an error";
	}
	catch (const InputError& e)
	{
		const std::string what = e.what();
		EXPECT_EQ(what.find('\n'), std::string::npos) << what;  // one line
		EXPECT_NE(what.find("robot.rawlog"), std::string::npos) << what;
		EXPECT_NE(what.find("--no-odometry"), std::string::npos) << what;
	}
	EXPECT_EQ(localizationSteps(log, "robot.rawlog", OdometryUse::optional).size(), 6u);
	// Ignored: zero increments even where there is odometry.
	for (const auto& s : localizationSteps(observationsRawlog(), "obs", OdometryUse::ignored))
		EXPECT_EQ(s.odometry, mrpt::poses::CPose2D());
}
