// CTagMap::asString(): the table RawLogViewer and friends print for a map
// (tagmap/tag_table.h: degrees, since this text is for people).
#include <mrpt/core/format.h>

#include "tagmap/maps/CTagMap.h"
#include "tagmap/tag_table.h"

namespace tagmap::maps
{
std::string CTagMap::asString() const
{
	const auto& ts = tags();
	return mrpt::format("CTagMap: %zu tags, %zu points\n", ts.size(), m_points.size()) + tagTable(ts);
}

}  // namespace tagmap::maps
