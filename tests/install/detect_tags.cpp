// The README's five lines, as a user's program would write them, plus a check
// that linking tagmap::maps is enough for MRPT to know CTagMap by name.
#include <mrpt/rtti/CObject.h>

#include <cstdio>

#include "tagmap/io/point_cloud_io.h"
#include "tagmap/maps/CTagMap.h"
#include "tagmap/pipeline.h"

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::fprintf(stderr, "usage: detect_tags MAP\n");
		return 2;
	}
	mrpt::maps::CPointsMapXYZI map = tagmap::io::loadPointCloud(argv[1]);
	tagmap::Pipeline pipeline(tagmap::PipelineParams::fromYamlFile(TAGMAP_DATA_DIR "/config/default.yaml"));
	tagmap::Detections found = pipeline.detect(map);
	for (const auto& t : found.tags) std::printf("%s %d\n", t.family.c_str(), t.id);

	tagmap::maps::CTagMap tagMap;
	tagMap.setTags(found.tags);
	const bool registered = mrpt::rtti::findRegisteredClass("tagmap::maps::CTagMap") != nullptr;
	std::printf("%zu tags; CTagMap %s\n", tagMap.tags().size(), registered ? "registered" : "NOT registered");
	return registered && !found.tags.empty() ? 0 : 1;
}
