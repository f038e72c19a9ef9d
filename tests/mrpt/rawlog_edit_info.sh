#!/usr/bin/env bash
# rawlog-edit reads our outputs: a stock one (no plugin) parses every object of
# the --rawlog without error and lists its CObservation3DScene; with the
# plugin (-p) it parses the --tagmap file (one CTagMap), which a stock one
# cannot (checked too, so the plugin is what makes the difference).
#   rawlog_edit_info.sh ARTIFACT_DIR PLUGIN.so [PREFIX]
set -euo pipefail
dir=$1 plugin=$2 prefix=${3:-map}
out=$dir/${prefix}_rawlog-edit-info.txt
rawlog-edit --info -i "$dir/$prefix.rawlog" </dev/null >"$out" 2>&1
cat "$out"
if grep -Eiq "exception|error" "$out"; then echo "FAIL: rawlog-edit reported an error"; exit 1; fi
grep -Eq "Observations format +: Yes" "$out"
grep -Eq "Overall number of objects +: 1$" "$out"
rawlog-edit --list-timestamps -i "$dir/$prefix.rawlog" --text-file-output "$dir/${prefix}_rawlog-classes.txt" \
  </dev/null >/dev/null 2>&1
cat "$dir/${prefix}_rawlog-classes.txt"
grep -q "mrpt::obs::CObservation3DScene" "$dir/${prefix}_rawlog-classes.txt"

tagmap_out=$dir/${prefix}_rawlog-edit-tagmap.txt
rawlog-edit -p "$plugin" --info -i "$dir/$prefix.tagmap" </dev/null >"$tagmap_out" 2>&1
if grep -Eiq "exception|error" "$tagmap_out"; then
  echo "FAIL: rawlog-edit with the plugin cannot read $prefix.tagmap:"; cat "$tagmap_out"; exit 1
fi
grep -Eq "Overall number of objects +: 1$" "$tagmap_out"
rawlog-edit --info -i "$dir/$prefix.tagmap" </dev/null >"$tagmap_out.stock" 2>&1
grep -q "tagmap::maps::CTagMap' which is not registered" "$tagmap_out.stock" ||
  { echo "FAIL: a stock rawlog-edit read $prefix.tagmap: the check above proves nothing"; exit 1; }
echo "rawlog-edit: $prefix.rawlog read by stock MRPT, $prefix.tagmap with the plugin"
