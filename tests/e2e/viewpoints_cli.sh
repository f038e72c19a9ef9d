#!/usr/bin/env bash
# `tagmap detect --viewpoints`: a point-cloud map with the trajectory it was
# built from. share/scenes/mirrored.yaml's pillar scanned from its west
# station only: the mirror image of the mirror-printed sheet reads as
# tag36h11 200 with its printed face into the pillar, which the points
# alone cannot contradict (nothing was scanned behind it). With the
# station's pose (the simulator's trajectory_drifted.tum) no line from that
# face reaches a sensor: no tag. The simplemap of the same scan brings the
# station itself. Usage: TAGMAP=/path/to/tagmap bash viewpoints_cli.sh
set -euo pipefail
: "${TAGMAP:?set TAGMAP to the tagmap binary}"
here=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tagmap-viewpoints.XXXXXX")
trap 'rm -rf "$work"' EXIT
# The scene with its first (west) station only: the lines after it, up to
# the next key, are dropped.
awk '/^    waypoints:/ {print; keep = 1; next} keep == 1 && /^      - / {if (++n > 1) next} {print}' \
	"$here/share/scenes/mirrored.yaml" >"$work/west.yaml"
[ "$(grep -c '^      - {position' "$work/west.yaml")" -eq 1 ] || { echo "FAIL: the scene edit kept no single station"; exit 1; }
"$TAGMAP" simulate "$work/west.yaml" --out "$work/sim" --simplemap --quiet
count200() { grep -c '"id": 200' "$1" || true; }
"$TAGMAP" detect "$work/sim/map.pcd" --json "$work/alone.json" --quiet
"$TAGMAP" detect "$work/sim/map.pcd" --json "$work/with.json" --viewpoints "$work/sim/trajectory_drifted.tum" --quiet
"$TAGMAP" detect "$work/sim/scans.simplemap" --json "$work/simplemap.json" --quiet
alone=$(count200 "$work/alone.json") with=$(count200 "$work/with.json") sm=$(count200 "$work/simplemap.json")
echo "tag36h11 200 reported: points alone $alone, with --viewpoints $with, from the simplemap $sm"
[ "$alone" -ge 1 ] || { echo "FAIL: the points alone no longer show the mirror read this test is for"; exit 1; }
[ "$with" -eq 0 ] || { echo "FAIL: --viewpoints did not reject the mirror image"; exit 1; }
[ "$sm" -eq 0 ] || { echo "FAIL: the simplemap's stations did not reject the mirror image"; exit 1; }
echo "viewpoints_cli: ok"
