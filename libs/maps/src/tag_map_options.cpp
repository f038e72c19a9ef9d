#include "tagmap/maps/tag_map_options.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/serialization/CArchive.h>

#include <string>

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

struct ArchiveWriter
{
	mrpt::serialization::CArchive& out;
	template <class T>
	void operator()(const char*, const T& v) const
	{
		out << v;
	}
};

struct ArchiveReader
{
	mrpt::serialization::CArchive& in;
	const char* firstMissing = nullptr;  // this field and those after it are not stored
	mutable bool missing = false;
	template <class T>
	void operator()(const char* k, T& v) const
	{
		missing = missing || (firstMissing && std::string(k) == firstMissing);
		if (!missing) in >> v;
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
	f("tagPoseMinStdPosition", o.tagPoseMinStdPosition);
	f("tagPoseMinStdRotationDeg", o.tagPoseMinStdRotationDeg);
	f("mapTagStdPosition", o.mapTagStdPosition);
	f("mapTagStdRotationDeg", o.mapTagStdRotationDeg);
	f("tagPoseOutlierSigmas", o.tagPoseOutlierSigmas);
	f("tagPoseExtraStdPosition", o.tagPoseExtraStdPosition);
	f("tagPoseExtraStdRotationDeg", o.tagPoseExtraStdRotationDeg);
	f("scoreBeaconRanges", o.scoreBeaconRanges);  // new in CTagMap version 4: keep it last
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

void writeLikelihoodOptions(mrpt::serialization::CArchive& out, const TTagLikelihoodOptions& o)
{
	likelihoodFields(o, ArchiveWriter{out});
}
void readLikelihoodOptions(mrpt::serialization::CArchive& in, TTagLikelihoodOptions& o, LikelihoodOptionsLayout stored)
{
	likelihoodFields(o, ArchiveReader{in, stored == LikelihoodOptionsLayout::v3 ? "scoreBeaconRanges" : nullptr});
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
