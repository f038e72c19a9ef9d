// Scenes from YAML (share/scenes/*.yaml; format in share/scenes/README.md).
// Any mistake -> tagmap::InputError "<file>: <key path>: <what is wrong>".
#pragma once

#include <map>
#include <string>

#include "tagmap/sim/scene.h"

namespace tagmap::sim
{
/** Values for the scene's `parameters:` (e.g. {"tag_distance", 4.0}),
 *  overriding its defaults; referenced in the YAML as "$name". */
using SceneParameters = std::map<std::string, double>;

Scene loadScene(const std::string& path, const SceneParameters& overrides = {});

/** Same from text; `sourceName` is used in error messages. */
Scene parseScene(const std::string& yamlText, const std::string& sourceName, const SceneParameters& overrides = {});

}  // namespace tagmap::sim
