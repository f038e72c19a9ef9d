#include "tagmap/maps/tag_map_options.h"

#include <mrpt/config/CConfigFileBase.h>

namespace tagmap::maps
{
namespace
{
// Each struct lists its keys once (the *Fields functions); loading and saving
// are the same walk with a different visitor, so the two can never disagree.
struct Loader
{
	const mrpt::config::CConfigFileBase& src;
	const std::string& sec;
	void operator()(const char* k, std::string& v) const { v = src.read_string(sec, k, v); }
	void operator()(const char* k, double& v) const { v = src.read_double(sec, k, v); }
	void operator()(const char* k, bool& v) const { v = src.read_bool(sec, k, v); }
};

struct Saver
{
	mrpt::config::CConfigFileBase& dst;
	const std::string& sec;
	template <class T>
	void operator()(const char* k, const T& v) const
	{
		dst.write(sec, k, v);
	}
};

template <class O, class F>
void detectionFields(O& o, const F& f)
{
	f("families", o.families);
	f("tagSize", o.tagSize);
	f("configFile", o.configFile);
}

template <class O, class F>
void likelihoodFields(O& o, const F& f)
{
	f("beaconRangesStd", o.beaconRangesStd);
	f("beaconRangesUseObservationStd", o.beaconRangesUseObservationStd);
}

template <class O, class F>
void visualFields(O& o, const F& f)
{
	f("showPoints", o.showPoints);
	f("showLabels", o.showLabels);
	f("showAxes", o.showAxes);
	f("pointSize", o.pointSize);
}
}  // namespace

void TTagDetectionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& s, const std::string& sec)
{
	detectionFields(*this, Loader{s, sec});
}
void TTagDetectionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& t, const std::string& sec) const
{
	detectionFields(*this, Saver{t, sec});
}

DetectionChoices detectionChoices(const TTagDetectionOptions& o)
{
	DetectionChoices c;
	c.configFile = o.configFile;
	c.families = o.families;
	c.tagSize = o.tagSize;
	return c;
}

void TTagLikelihoodOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& s, const std::string& sec)
{
	likelihoodFields(*this, Loader{s, sec});
}
void TTagLikelihoodOptions::saveToConfigFile(mrpt::config::CConfigFileBase& t, const std::string& sec) const
{
	likelihoodFields(*this, Saver{t, sec});
}

void TTagVisualOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& s, const std::string& sec)
{
	visualFields(*this, Loader{s, sec});
}
void TTagVisualOptions::saveToConfigFile(mrpt::config::CConfigFileBase& t, const std::string& sec) const
{
	visualFields(*this, Saver{t, sec});
}

}  // namespace tagmap::maps
