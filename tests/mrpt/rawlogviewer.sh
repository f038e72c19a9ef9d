#!/usr/bin/env bash
# RawLogViewer with our plugin (-l) opens the --tagmap file (one CTagMap, a
# valid one-entry rawlog), logs no error, and its 3D view shows the map with
# the tags' patterns (the plugin's getVisualizationInto). Screenshots kept in
# the artifacts folder.
#   rawlogviewer.sh ARTIFACT_DIR PLUGIN.so [PREFIX [ORBIT_DX ORBIT_DY ZOOM]]
# PREFIX names the inputs PREFIX.tagmap and the outputs (default: map); the
# camera moves bring RawLogViewer's fixed start view (around the origin) to
# the tags of the fixture's wall.
set -euo pipefail
dir=$1 plugin=$2 prefix=${3:-map}
here=$(dirname "$0")
bash "$here/gui_screenshot.sh" "$dir/${prefix}_rawlogviewer.png" "$dir/${prefix}_rawlogviewer.log" \
  "gui_rawlogviewer_3d 0 ${4:-450} ${5:--325} ${6:-10}" \
  RawLogViewer -l "$plugin" "$dir/$prefix.tagmap"
