#!/usr/bin/env bash
# A stock RawLogViewer (no plugin) opens our --rawlog without any error and its
# 3D view shows the map with the tags' patterns. RawLogViewer puts load
# errors only in its "End of load message" tab, never on stdout, so the same
# MRPT reader is run first through a stock rawlog-edit, which prints them.
#   rawlogviewer_stock.sh ARTIFACT_DIR PLUGIN.so [PREFIX [ORBIT_DX ORBIT_DY ZOOM]]
# (PLUGIN.so unused: the point is not to load it.)
set -euo pipefail
dir=$1 prefix=${3:-map}
here=$(dirname "$0")
rawlog-edit --info -i "$dir/$prefix.rawlog" </dev/null >"$dir/${prefix}_rawlog-edit-stock.txt" 2>&1
if grep -Eiq "exception|error" "$dir/${prefix}_rawlog-edit-stock.txt"; then
  echo "FAIL: a stock MRPT cannot read all of $prefix.rawlog:"; cat "$dir/${prefix}_rawlog-edit-stock.txt"; exit 1
fi
bash "$here/gui_screenshot.sh" "$dir/${prefix}_rawlogviewer_stock.png" "$dir/${prefix}_rawlogviewer_stock.log" \
  "gui_rawlogviewer_3d 0 ${4:-450} ${5:--325} ${6:-10}" \
  RawLogViewer "$dir/$prefix.rawlog"
