#!/usr/bin/env bash
# SceneViewer3D opens our .3Dscene (stock MRPT, no plugin) without errors and
# starts from the scene's camera, aimed at the tags: their patterns are in
# the first view, no camera moves. Screenshots kept in the artifacts folder.
#   scene_viewer.sh ARTIFACT_DIR PLUGIN.so [PREFIX]
set -euo pipefail
dir=$1 prefix=${3:-map}
here=$(dirname "$0")
bash "$here/gui_screenshot.sh" "$dir/${prefix}_sceneviewer3d.png" "$dir/${prefix}_sceneviewer3d.log" \
  gui_sceneviewer_3d SceneViewer3D "$dir/$prefix.3Dscene"
