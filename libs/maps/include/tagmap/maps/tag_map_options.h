// CTagMap's parameter structs, loadable from an MRPT ini section like every
// MRPT map's insertion/likelihood options.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

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

/** Range-only likelihood, as CLandmarksMap/CBeaconMap model it (section
 *  "<prefix>_likelihoodOpts"; same key names as CLandmarksMap). */
struct TTagLikelihoodOptions : public mrpt::config::CLoadableOptions
{
	double beaconRangesStd = 0.08;  // metres
	bool beaconRangesUseObservationStd = false;  // use each observation's stdError instead

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

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
