#!/usr/bin/env bash
# RawLogViewer opens our rawlog with the plugin loaded (-l), without errors,
# and draws something. Screenshot kept in the artifacts folder.
#   rawlogviewer.sh ARTIFACT_DIR PLUGIN.so
set -euo pipefail
dir=$1 plugin=$2
here=$(dirname "$0")
bash "$here/gui_screenshot.sh" "$dir/rawlogviewer.png" "$dir/rawlogviewer.log" 8 \
  RawLogViewer -l "$plugin" "$dir/map.rawlog"
