#!/usr/bin/env bash
# rawlog-edit reads our rawlog: with the plugin (-p) it parses every object
# without error, and lists the CObservation3DScene; the CTagMap follows it.
#   rawlog_edit_info.sh ARTIFACT_DIR PLUGIN.so
set -euo pipefail
dir=$1 plugin=$2
out=$dir/rawlog-edit-info.txt
rawlog-edit -p "$plugin" --info -i "$dir/map.rawlog" </dev/null >"$out" 2>&1
cat "$out"
if grep -Eiq "exception|error" "$out"; then echo "FAIL: rawlog-edit reported an error"; exit 1; fi
grep -Eq "Observations format +: Yes" "$out"
rawlog-edit -p "$plugin" --list-timestamps -i "$dir/map.rawlog" --text-file-output "$dir/rawlog-classes.txt" \
  </dev/null >/dev/null 2>&1
cat "$dir/rawlog-classes.txt"
grep -q "mrpt::obs::CObservation3DScene" "$dir/rawlog-classes.txt"
