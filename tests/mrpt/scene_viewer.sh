#!/usr/bin/env bash
# SceneViewer3D opens our .3Dscene (stock MRPT, no plugin) without errors and
# draws something. Screenshot kept in the artifacts folder.
#   scene_viewer.sh ARTIFACT_DIR PLUGIN.so
set -euo pipefail
dir=$1
here=$(dirname "$0")
bash "$here/gui_screenshot.sh" "$dir/sceneviewer3d.png" "$dir/sceneviewer3d.log" 8 \
  SceneViewer3D "$dir/map.3Dscene"
