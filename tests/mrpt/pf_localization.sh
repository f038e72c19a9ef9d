#!/usr/bin/env bash
# Stock pf-localization localizes on our --ini map: a robot observing ranges to
# the tags (a beacons rawlog, IDs per docs/MRPT.md) runs to the end without
# errors, writes its output files, reads every tag of the map as a beacon and
# ends within 0.25 m of where the robot ended.
#   pf_localization.sh ARTIFACT_DIR PLUGIN.so [PREFIX BEACONS.rawlog END_X END_Y [KEY=VALUE...]]
# The experiment is share/mrpt/pf-localization.ini (the README's) with each
# KEY=VALUE replacing its line, followed by PREFIX.ini unchanged.
# Without PREFIX...: the fixture, make_fixture.cpp (map.ini, beacons.rawlog
# ending at x=3.4, y=0.45, starting near the origin).
# The app runs stock (the tagMap of PREFIX.ini is then ignored), or with
# PF_LOCALIZATION_PRELOAD=PLUGIN.so in the environment with the plugin
# preloaded, so the tagMap loads and scores the tag poses (docs/MRPT.md).
set -euo pipefail
if [ $# -le 2 ]; then
  set -- "$@" map beacons.rawlog 3.4 0.45 init_PDF_min_x=-1 init_PDF_max_x=3 init_PDF_min_y=-2 init_PDF_max_y=1 \
    init_PDF_min_yaw_deg=-30 init_PDF_max_yaw_deg=60
fi
dir=$(cd "$1" && pwd)
experiment=$(cd "$(dirname "$0")/../../share/mrpt" && pwd)/pf-localization.ini
prefix=$3 beacons=$4 end_x=$5 end_y=$6
shift 6
cd "$dir"
run=${prefix}_pf_localization_run.ini log=${prefix}_pf_localization.log
cp "$experiment" "$run"
for kv in "$@"; do
  grep -q "^${kv%%=*}=" "$run" || { echo "FAIL: $experiment has no key ${kv%%=*}"; exit 1; }
  sed -i "s|^${kv%%=*}=.*|$kv|" "$run"
done
cat "$prefix.ini" >>"$run"
out=$(sed -n 's/^logOutput_dir=//p' "$run")
rm -rf "${out}"_*
LD_PRELOAD=${PF_LOCALIZATION_PRELOAD:-} pf-localization "$run" "$beacons" </dev/null >"$log" 2>&1 || {
  echo "FAIL: pf-localization exited non-zero"; tail -40 "$log"; exit 1; }
if grep -q "MRPT exception" "$log"; then tail -40 "$log"; exit 1; fi
out=$(ls -d "${out}"_*/ | head -1)
for f in PF_stats.txt odo_est.txt cov_est.txt; do
  test -s "$out/$f" || { echo "FAIL: $out/$f missing or empty"; exit 1; }
done
# The tags reached the filter as beacons: the map dump lists them.
n=$(sed -n 's/^nBeacons=//p' "$prefix.ini")
grep -q "number of initial beacons *= $n$" "$log" || { echo "FAIL: pf-localization did not load $n beacons"; exit 1; }
last=$(grep "PDF estimation" "$log" | tail -1)
echo "$last"
echo "$last" | sed -E 's/.*PDF estimation: \(([-0-9.]+),([-0-9.]+),.*/\1 \2/' |
  awk -v x="$end_x" -v y="$end_y" '{ d = sqrt(($1 - x)^2 + ($2 - y)^2); print "final position error " d " m"; exit !(d < 0.25) }'
echo "pf-localization output: $dir/$out"
