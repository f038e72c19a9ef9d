#include "tagmap/localize/pf_localizer.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <mrpt/maps/CMultiMetricMap.h>

#include "tagmap/localize/tag_relocalization.h"
#include "tagmap/maps/CTagMap.h"

namespace tagmap::localize
{
namespace
{
struct Bounds
{
	double xmin = 1e18, xmax = -1e18, ymin = 1e18, ymax = -1e18;
};

Bounds mapBounds(const std::vector<TagDetection>& tags, double margin)
{
	Bounds b;
	for (const auto& t : tags)
	{
		b.xmin = std::min(b.xmin, t.position().x() - margin);
		b.xmax = std::max(b.xmax, t.position().x() + margin);
		b.ymin = std::min(b.ymin, t.position().y() - margin);
		b.ymax = std::max(b.ymax, t.position().y() + margin);
	}
	return b;
}

/** One 2D movement action: `odometry` under the motion `model`. */
mrpt::obs::CActionCollection movementAction(const mrpt::poses::CPose2D& odometry,
											const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& model,
											mrpt::Clock::time_point stamp = {})
{
	mrpt::obs::CActionRobotMovement2D move;
	move.timestamp = stamp;
	move.computeFromOdometry(odometry, model);
	mrpt::obs::CActionCollection actions;
	actions.insert(move);
	return actions;
}

/** The step's odometry under the filter's motion model (a zero increment
 *  when the robot did not move: the PF needs an action). Without odometry,
 *  a zero increment with noise for `dt` seconds of unknown motion. */
mrpt::obs::CActionCollection actionsOf(const LocalizationStep& s, double dt, const PfParams& params)
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions model = params.motionModel;
	mrpt::poses::CPose2D odometry = s.odometry;
	if (params.noOdometry)
	{
		odometry = mrpt::poses::CPose2D();
		auto& g = model.gaussianModel;
		g.minStdXY = std::max<double>(g.minStdXY, params.noOdometrySpeed * dt);
		g.minStdPHI = std::max<double>(g.minStdPHI, mrpt::DEG2RAD(params.noOdometryTurnRateDeg) * dt);
	}
	return movementAction(odometry, model, s.tags->timestamp);
}

struct Spread
{
	double position = 0;  // metres, the larger axis
	double heading = 0;  // radians
};

/** Systematic resampling of the belief to `count` equally weighted
 *  particles. MRPT 2.5's performResampling(options, count) is only right for
 *  count == size(): with fewer it draws from the first count/size of the
 *  weight CDF only, with more it reads past its own array (and hangs). */
void resampleTo(mrpt::slam::CMonteCarloLocalization2D& pdf, size_t count)
{
	const size_t n = pdf.size();
	double maxLogW = -std::numeric_limits<double>::infinity();
	for (size_t i = 0; i < n; i++) maxLogW = std::max(maxLogW, pdf.getW(i));
	std::vector<double> cdf(n);
	double sum = 0;
	for (size_t i = 0; i < n; i++)
	{
		// All weights -inf (no particle explains the ranges): treat as equal.
		const double w = std::isfinite(maxLogW) ? std::exp(pdf.getW(i) - maxLogW) : 1.0;
		cdf[i] = sum += std::isfinite(w) ? w : 0.0;
	}
	const double step = sum / static_cast<double>(count);
	double u = mrpt::random::getRandomGenerator().drawUniform(0.0, step);
	std::vector<size_t> picks(count);
	for (size_t i = 0, j = 0; i < count; i++, u += step)
	{
		while (j + 1 < n && cdf[j] < u) j++;
		picks[i] = j;
	}
	pdf.performSubstitution(picks);
	for (size_t i = 0; i < count; i++) pdf.setW(i, 0);
}

Spread spreadOf(const mrpt::slam::CMonteCarloLocalization2D& pdf)
{
	const auto [cov, mean] = pdf.getCovarianceAndMean();
	return {std::sqrt(std::max(cov(0, 0), cov(1, 1))), std::sqrt(cov(2, 2))};
}
}  // namespace

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions PfParams::defaultMotionModel()
{
	// Gaussian: 5 % of the distance and 2 deg per metre, plus a floor per
	// step so a resampled (duplicated) particle set spreads out again.
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
	m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	m.gaussianModel.a1 = 0.05;
	m.gaussianModel.a2 = 0.001;
	m.gaussianModel.a3 = mrpt::DEG2RAD(2.0);
	m.gaussianModel.a4 = 0.05;
	m.gaussianModel.minStdXY = 0.02;
	m.gaussianModel.minStdPHI = mrpt::DEG2RAD(0.5);
	return m;
}

namespace
{
/** Ranges: the std follows the belief's position spread (see the header). */
void annealRanges(maps::TTagLikelihoodOptions& o, const PfParams& params, const Spread& spread)
{
	o.beaconRangesStd = std::clamp(spread.position, params.trackingRangeStd, params.globalRangeStd);
}

/** Tag poses: the belief's spread added to every tag's std, capped. */
void annealPoses(maps::TTagLikelihoodOptions& o, const PfParams& params, const Spread& spread, bool converged)
{
	const double width = converged ? params.trackingAnnealWidth : params.annealWidth;
	o.tagPoseExtraStdPosition = std::min(width * spread.position, params.globalPoseStdPosition);
	o.tagPoseExtraStdRotationDeg = std::min(width * mrpt::RAD2DEG(spread.heading), params.globalPoseStdRotationDeg);
}

/** No motion, a little noise: a resampled set (duplicates) spreads out
 *  between annealing passes, a fraction of the belief's spread. */
mrpt::obs::CActionCollection jitterOf(const Spread& spread, const PfParams& params)
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m = PfParams::defaultMotionModel();
	m.gaussianModel.minStdXY = params.annealJitter * spread.position;
	m.gaussianModel.minStdPHI = params.annealJitter * spread.heading;
	return movementAction(mrpt::poses::CPose2D(), m);
}

/** Where the scan's tags alone put the robot's base: the relocalized sensor
 *  pose (tag_relocalization.h), moved by `mount^-1`, on the ground plane. */
class TagFix
{
   public:
	using Vector6d = Eigen::Matrix<double, 6, 1>;

	/** None without a relocalized pose, or with a covariance that is not
	 *  positive definite (nothing to draw from). */
	static std::optional<TagFix> of(const std::optional<PoseWithCovariance>& sensor, const mrpt::poses::CPose3D& mount)
	{
		if (!sensor) return std::nullopt;
		const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(sensor->covariance);
		if (llt.info() != Eigen::Success) return std::nullopt;
		return TagFix(*sensor, mount, llt.matrixL());
	}

	/** The base pose for a draw `d` of [x y z | rx ry rz] from the unit
	 *  normal: the sensor pose perturbed as its covariance says. */
	mrpt::poses::CPose2D base(const Vector6d& d) const
	{
		const Vector6d e = sqrtCov_ * d;
		Eigen::Isometry3d s = sensor_.pose;
		const double angle = e.tail<3>().norm();
		if (angle > 0) s.linear() = Eigen::AngleAxisd(angle, e.tail<3>() / angle).toRotationMatrix() * s.linear();
		s.translation() += e.head<3>();
		const Eigen::Matrix4d b = s.matrix() * mountInv_;
		return {b(0, 3), b(1, 3), std::atan2(b(1, 0), b(0, 0))};
	}
	mrpt::poses::CPose2D base() const { return base(Vector6d::Zero()); }

   private:
	TagFix(const PoseWithCovariance& sensor, const mrpt::poses::CPose3D& mount, const Eigen::Matrix<double, 6, 6>& sqrtCov)
		: sensor_(sensor),
		  mountInv_(mount.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen().inverse()),
		  sqrtCov_(sqrtCov)
	{
	}

	PoseWithCovariance sensor_;
	Eigen::Matrix4d mountInv_;
	Eigen::Matrix<double, 6, 6> sqrtCov_;
};

/** Sensor resetting (Lenser and Veloso 2000; the dual proposal of Thrun et
 *  al.'s Mixture MCL): a fraction of the particles is drawn where the
 *  scan's tags alone put the robot, before the update weighs them all. A
 *  belief that locked on some centimetres off (a uniform start's first
 *  sighting, the end of a gap on odometry) otherwise moves towards the tags
 *  only by each step's motion noise: the update cannot choose a pose no
 *  particle holds (Livox run: 20 cm after the first tag, still 4 cm seven
 *  tagged scans later). The draws keep their slots' weights: Mixture MCL
 *  would weigh them by the predicted belief, which undoes the reset exactly
 *  when that belief is confidently wrong (odometry worse than the motion
 *  model: test TheFirstTagAfterAGapPullsTheBeliefBack, 21 cm instead of
 *  1.7 cm). Once converged, a fix the predicted belief makes implausible
 *  (Mahalanobis^2 over both covariances above `resetGate`: a misread or
 *  wrongly mapped tag) is not drawn at all. Returns the particles drawn. */
size_t resetFromTags(mrpt::slam::CMonteCarloLocalization2D& pdf, const TagFix& fix, bool gated, const PfParams& params)
{
	const size_t n = pdf.size(), m = static_cast<size_t>(params.resetFraction * static_cast<double>(n));
	if (m == 0) return 0;
	auto& rng = mrpt::random::getRandomGenerator();
	std::vector<mrpt::poses::CPose2D> draws(m);
	for (auto& d : draws)
	{
		TagFix::Vector6d u;
		for (int k = 0; k < 6; k++) u(k) = rng.drawGaussian1D_normalized();
		d = fix.base(u);
	}
	if (gated)
	{
		const mrpt::poses::CPose2D at = fix.base();
		Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
		for (const auto& d : draws)
		{
			const Eigen::Vector3d e(d.x() - at.x(), d.y() - at.y(), mrpt::math::wrapToPi(d.phi() - at.phi()));
			cov += e * e.transpose() / static_cast<double>(m);
		}
		const auto [beliefCov, belief] = pdf.getCovarianceAndMean();
		const Eigen::Vector3d diff(at.x() - belief.x(), at.y() - belief.y(),
								   mrpt::math::wrapToPi(at.phi() - belief.phi()));
		cov += beliefCov.asEigen();
		if (diff.dot(cov.ldlt().solve(diff)) > params.resetGate) return 0;
	}
	for (size_t j = 0; j < m; j++) pdf.m_particles[j * n / m].d = draws[j].asTPose();
	return m;
}

/** Tag poses, one step: predict, then update in passes with the likelihood
 *  as wide as the belief, narrowing as the belief does (annealing), until it
 *  stops narrowing. One update at the final width would leave a uniform
 *  start's 40 000 particles with a handful, or none, near the truth (a wrong
 *  particle then wins and the sharp model cannot move it: every tag is an
 *  outlier there); a broad update alone would leave a broad estimate. */
Spread updateWithPoses(mrpt::bayes::CParticleFilter& pf, mrpt::slam::CMonteCarloLocalization2D& pdf,
					   maps::TTagLikelihoodOptions& o, const mrpt::obs::CActionCollection& actions,
					   const mrpt::obs::CSensoryFrame& sf, const std::optional<TagFix>& fix, bool converged,
					   const PfParams& params)
{
	const mrpt::obs::CSensoryFrame none;
	pf.executeOn(pdf, &actions, &none);
	if (fix) resetFromTags(pdf, *fix, converged, params);
	Spread spread = spreadOf(pdf);
	mrpt::poses::CPose2D mean;
	pdf.getMean(mean);
	for (int pass = 0; !sf.empty() && pass < params.annealPasses; pass++)
	{
		annealPoses(o, params, spread, converged);
		const mrpt::obs::CActionCollection jitter = jitterOf(spread, params);
		pf.executeOn(pdf, &jitter, &sf);
		const Spread before = spread;
		const mrpt::poses::CPose2D meanBefore = mean;
		spread = spreadOf(pdf);
		pdf.getMean(mean);
		// Done when the belief neither narrows nor travels: after a uniform
		// start it can stop narrowing at a few cm while its mean still moves
		// by as much per pass towards the truth (stopped there, the first
		// estimate was 12 cm off, by the luck of the seed).
		const bool travelling = (mean.translation() - meanBefore.translation()).norm() > 0.5 * spread.position;
		if (spread.position > 0.8 * before.position && spread.heading > 0.8 * before.heading && !travelling) break;
	}
	return spread;
}
}  // namespace

PfResult runParticleFilter(const std::vector<TagDetection>& mapTags, const std::vector<LocalizationStep>& steps,
						   const PfParams& params, const CountProgressFn& progress)
{
	if (mapTags.empty()) throw std::invalid_argument("the tag map is empty");
	// The tag map as MRPT's apps hold it: a CTagMap in a CMultiMetricMap.
	auto tagMap = maps::CTagMap::Create();
	tagMap->setTags(mapTags);
	tagMap->likelihoodOptions.beaconRangesUseObservationStd = false;
	auto map = mrpt::maps::CMultiMetricMap::Create();
	map->maps.push_back(tagMap);

	mrpt::slam::CMonteCarloLocalization2D pdf(params.globalParticles);
	pdf.options.metricMap = map;
	// Seeded here, after MRPT's constructors: runs are repeatable.
	mrpt::random::getRandomGenerator().randomize(params.seed);
	const Bounds b = mapBounds(mapTags, params.mapMargin);
	pdf.resetUniform(b.xmin, b.xmax, b.ymin, b.ymax, -M_PI, M_PI, static_cast<int>(params.globalParticles));
	annealRanges(tagMap->likelihoodOptions, params, spreadOf(pdf));

	mrpt::bayes::CParticleFilter pf;
	pf.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	pf.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
	pf.m_options.adaptiveSampleSize = false;

	PfResult r;
	for (size_t k = 0; k < steps.size(); k++)
	{
		const LocalizationStep& s = steps[k];
		const double dt = k > 0 ? s.stamp - steps[k - 1].stamp : 0.0;
		const mrpt::obs::CActionCollection actions = actionsOf(s, dt, params);
		// One model only: the map scores both observation types, and the
		// ranges repeat what the poses say (counted twice, they would make
		// the filter overconfident). The scan itself means nothing to a tag map.
		mrpt::obs::CSensoryFrame sf;
		Spread spread;
		if (params.observations == PfObservations::tagPoses)
		{
			if (!s.tags->tags.empty()) sf.insert(s.tags);
			const std::optional<TagFix> fix = TagFix::of(relocalize(mapTags, s.tags->tags), s.sensorPose);
			spread = updateWithPoses(pf, pdf, tagMap->likelihoodOptions, actions, sf, fix, r.convergedAtStep >= 0,
									 params);
		}
		else
		{
			if (!s.ranges->sensedData.empty()) sf.insert(s.ranges);
			pf.executeOn(pdf, &actions, &sf);
			spread = spreadOf(pdf);
			annealRanges(tagMap->likelihoodOptions, params, spread);
		}

		// Ranges say nothing about heading: a tight position blob can still
		// hold every heading, so convergence needs both spreads small.
		if (r.convergedAtStep < 0 && spread.position < params.convergedSpread &&
			spread.heading < params.convergedHeadingDeg * M_PI / 180)
		{
			r.convergedAtStep = static_cast<long>(k);
			resampleTo(pdf, params.trackingParticles);
		}
		mrpt::poses::CPose2D mean;
		pdf.getMean(mean);
		StampedPose p;
		p.stamp = s.stamp;
		p.pose.matrix() =
			(mrpt::poses::CPose3D(mean) + s.sensorPose).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
		r.trajectory.push_back(p);
		r.spread.push_back(spread.position);
		if (progress) progress(k + 1, steps.size());
	}
	return r;
}

}  // namespace tagmap::localize
