// The tagmap MRPT plugin: all it does is register tagmap's classes when an
// MRPT app loads it (`RawLogViewer -l`, `SceneViewer3D -l`, `rawlog-edit -p`,
// dlopen). The classes themselves live in libs/maps (tagmap_maps), which
// tagmap's own programs link directly; nothing links this module.
#include <mrpt/core/initializer.h>

#include "tagmap/maps/register_classes.h"

MRPT_INITIALIZER(tagmap_plugin_register_classes) { tagmap::maps::registerClasses(); }
