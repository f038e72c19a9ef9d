#!/usr/bin/env bash
# Stock pf-localization localizes on our --ini map: a robot observing ranges to
# the tags (beacons.rawlog, IDs per docs/MRPT.md) runs to the end without
# errors and writes its output files.
#   pf_localization.sh ARTIFACT_DIR PLUGIN.so
set -euo pipefail
dir=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
cd "$dir"
rm -rf pf_out_*
cat "$here/pf_localization.ini" map.ini >pf_localization_run.ini
pf-localization pf_localization_run.ini beacons.rawlog </dev/null >pf_localization.log 2>&1 || {
  echo "FAIL: pf-localization exited non-zero"; tail -40 pf_localization.log; exit 1; }
if grep -q "MRPT exception" pf_localization.log; then tail -40 pf_localization.log; exit 1; fi
out=$(ls -d pf_out_* | head -1)
for f in PF_stats.txt odo_est.txt cov_est.txt; do
  test -s "$out/$f" || { echo "FAIL: $out/$f missing or empty"; exit 1; }
done
# The tags reached the filter as beacons: the map dump lists them.
grep -q "number of initial beacons *= 3" pf_localization.log
# beacons.rawlog ends at x=3.4, y=0.45 (make_fixture.cpp): the filter must be there.
last=$(grep "PDF estimation" pf_localization.log | tail -1)
echo "$last"
echo "$last" | sed -E 's/.*PDF estimation: \(([-0-9.]+),([-0-9.]+),.*/\1 \2/' |
  awk '{ d = sqrt(($1 - 3.4)^2 + ($2 - 0.45)^2); print "final position error " d " m"; exit !(d < 0.25) }'
echo "pf-localization output: $dir/$out"
