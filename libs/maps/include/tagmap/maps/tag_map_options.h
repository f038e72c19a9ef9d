// CTagMap's parameter structs, loadable from an MRPT ini section like every
// MRPT map's insertion/likelihood options.
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/serialization/CArchive.h>

#include <string>

#include "tagmap/detection_settings.h"

namespace tagmap::maps
{
/** How tags are detected in the accumulated points (section
 *  "<prefix>_detectionOpts"). Empty/zero values keep the pipeline's own
 *  defaults, so an ini only names what it changes. */
struct TTagDetectionOptions : public mrpt::config::CLoadableOptions
{
	std::string families;  // "tag36h11,aruco_4x4_50"; empty = every supported family
	double tagSize = 0;  // metres; 0 = any size in the pipeline's default range
	std::string configFile;  // pipeline YAML (share/config/*.yaml); empty = built-in defaults

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

/** The same choices for resolveDetectionSettings(). */
DetectionChoices detectionChoices(const TTagDetectionOptions& o);

/** Observation likelihoods (section "<prefix>_likelihoodOpts").
 *  CObservationBeaconRanges: range-only, as CLandmarksMap/CBeaconMap model
 *  it (same key names as CLandmarksMap).
 *  CObservationTagPoses: each seen tag's 6-DoF pose against the mapped tag,
 *  a Gaussian on the residual (the seen tag's covariance plus the map tag's)
 *  mixed with an outlier term (tag_pose_model.h). */
struct TTagLikelihoodOptions : public mrpt::config::CLoadableOptions
{
	double beaconRangesStd = 0.08;  // metres
	bool beaconRangesUseObservationStd = false;  // use each observation's stdError instead
	/** false: CObservationBeaconRanges give no information (log 1). For a
	 *  [MetricMap] that also holds a landmarksMap of the same tags (the ini of
	 *  `tagmap detect --ini`), which scores the ranges already: with both, a
	 *  CMultiMetricMap would count every range twice. */
	bool scoreBeaconRanges = true;

	/** Floors on a seen tag's standard deviations (metres, degrees): a
	 *  covariance from few points can be overconfident, and a zero one would
	 *  let one tag veto every particle not exactly on it. The values of
	 *  tagmap::localize::RelocalizationParams (direct relocalization). */
	double tagPoseMinStdPosition = 0.002;
	double tagPoseMinStdRotationDeg = 0.1;
	/** A map tag without a covariance (a `tagmap detect` JSON has none) is
	 *  taken as this uncertain: mapped tags are good to a few mm and tenths of
	 *  a degree (docs/ACCURACY.md). Metres, degrees. */
	double mapTagStdPosition = 0.005;
	double mapTagStdRotationDeg = 0.3;
	/** The outlier term is as likely as a residual this many standard
	 *  deviations (Mahalanobis) away, so a wrong association or a plane-fit
	 *  failure (30 deg yaw errors were seen with a 1.5 deg reported std)
	 *  costs every particle at most that much instead of zeroing them all.
	 *  5: a correct 6-DoF residual exceeds it with probability ~1e-4. */
	double tagPoseOutlierSigmas = 5;
	/** Added to every tag's standard deviations (metres, degrees; the
	 *  rotation also through the tag's range). 0 for tracking; a particle
	 *  filter widens it while its belief is spread (no particle lies within
	 *  millimetres of the truth from a uniform start). */
	double tagPoseExtraStdPosition = 0;
	double tagPoseExtraStdRotationDeg = 0;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

/** Every field in the order of the ini keys (CTagMap serialization). */
void writeLikelihoodOptions(mrpt::serialization::CArchive& out, const TTagLikelihoodOptions& o);
/** `stored`: the archive's fields, a prefix of the current ones (CTagMap
 *  version 3 has all but scoreBeaconRanges); the rest keep their defaults. */
enum class LikelihoodOptionsLayout { v3, current };
void readLikelihoodOptions(mrpt::serialization::CArchive& in, TTagLikelihoodOptions& o,
						   LikelihoodOptionsLayout stored = LikelihoodOptionsLayout::current);

/** What getVisualizationInto() draws (section "<prefix>_visualOpts"). */
struct TTagVisualOptions : public mrpt::config::CLoadableOptions
{
	bool showPoints = true;  // the accumulated points, coloured by intensity
	bool showLabels = true;
	bool showAxes = true;
	double pointSize = 2.0;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

}  // namespace tagmap::maps
