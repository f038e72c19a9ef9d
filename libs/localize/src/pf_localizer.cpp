#include "tagmap/localize/pf_localizer.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tagmap/mrpt/landmarks_map.h"

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

/** The step's odometry under the filter's motion model (a zero increment
 *  when the robot did not move: the PF needs an action). */
mrpt::obs::CActionCollection actionsOf(const LocalizationStep& s, const PfParams& params)
{
	mrpt::obs::CActionRobotMovement2D move;
	move.timestamp = s.tags->timestamp;
	move.computeFromOdometry(s.odometry, params.motionModel);
	mrpt::obs::CActionCollection actions;
	actions.insert(move);
	return actions;
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

PfResult runParticleFilter(const std::vector<TagDetection>& mapTags, const std::vector<LocalizationStep>& steps,
						   const PfParams& params, const CountProgressFn& progress)
{
	if (mapTags.empty()) throw std::invalid_argument("the tag map is empty");
	auto map = std::make_shared<mrpt::maps::CLandmarksMap>(mrpt_bridge::tagsToLandmarksMap(mapTags));
	map->likelihoodOptions.beaconRangesUseObservationStd = false;
	map->likelihoodOptions.beaconRangesStd = static_cast<float>(params.globalRangeStd);

	mrpt::slam::CMonteCarloLocalization2D pdf(params.globalParticles);
	pdf.options.metricMap = map;
	// Seeded here, after MRPT's constructors: runs are repeatable.
	mrpt::random::getRandomGenerator().randomize(params.seed);
	const Bounds b = mapBounds(mapTags, params.mapMargin);
	pdf.resetUniform(b.xmin, b.xmax, b.ymin, b.ymax, -M_PI, M_PI, static_cast<int>(params.globalParticles));

	mrpt::bayes::CParticleFilter pf;
	pf.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	pf.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
	pf.m_options.adaptiveSampleSize = false;

	PfResult r;
	for (size_t k = 0; k < steps.size(); k++)
	{
		const LocalizationStep& s = steps[k];
		const mrpt::obs::CActionCollection actions = actionsOf(s, params);
		// Only the ranges: the scan itself means nothing to a beacon map.
		mrpt::obs::CSensoryFrame sf;
		if (!s.ranges->sensedData.empty()) sf.insert(s.ranges);
		pf.executeOn(pdf, &actions, &sf);

		// Ranges say nothing about heading: a tight position blob can still
		// hold every heading, so convergence needs both spreads small.
		const Spread spread = spreadOf(pdf);
		if (r.convergedAtStep < 0 && spread.position < params.convergedSpread &&
			spread.heading < params.convergedHeadingDeg * M_PI / 180)
		{
			r.convergedAtStep = static_cast<long>(k);
			resampleTo(pdf, params.trackingParticles);
		}
		// Anneal: the likelihood is about as wide as the belief.
		map->likelihoodOptions.beaconRangesStd =
			static_cast<float>(std::clamp(spread.position, params.trackingRangeStd, params.globalRangeStd));
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
