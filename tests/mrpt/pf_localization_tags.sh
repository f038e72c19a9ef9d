#!/usr/bin/env bash
# Stock pf-localization localizes with the tag poses: the quick localize demo's
# outputs (scripts/localize-demo.sh --quick: tags.ini from `tagmap detect --ini`,
# robot/obs.rawlog from `tagmap observe`, robot/trajectory_true.tum), the plugin
# LD_PRELOADed so the ini's tagMap loads and scores each CObservationTagPoses,
# a uniform initial belief over the whole site (the tags' bounding box + 3 m,
# every heading), no GUI, no stdin. The app's "PDF estimation" after each
# step is scored against the truth:
#   converged (<= 0.3 m and <= 10 deg from then to the end) by step MAX_STEP,
#   and from step FROM on translation RMSE <= MAX_T m, rotation RMSE <= MAX_R deg.
#   pf_localization_tags.sh DEMO_DIR PLUGIN.so [PARTICLES]
# Writes DEMO_DIR/tags_pf_localization.log, tags_pf_errors.txt (step, m, deg).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dir=$(cd "$1" && pwd) plugin=$(realpath "$2") particles=${3:-100000}  # the app runs in DIR
from=5 max_step=5 max_t=0.015 max_r=0.1  # measured: step 1-2, 8.5-8.9 mm, 0.025-0.028 deg
for f in tags.ini robot/obs.rawlog robot/trajectory_true.tum; do
  test -s "$dir/$f" || { echo "FAIL: $dir/$f missing (run scripts/localize-demo.sh --quick --out $dir)"; exit 1; }
done
grep -q "^tagMap_count=1" "$dir/tags.ini" || { echo "FAIL: tags.ini declares no tagMap"; exit 1; }
# The site: the tags' bounding box + 3 m.
read -r x0 x1 y0 y1 < <(awk -F= '/^beacon_[0-9]+_x=/ { x[++n] = $2 } /^beacon_[0-9]+_y=/ { y[++m] = $2 }
  END { a = b = x[1]; c = d = y[1]; for (i = 1; i <= n; i++) { if (x[i] < a) a = x[i]; if (x[i] > b) b = x[i] }
        for (i = 1; i <= m; i++) { if (y[i] < c) c = y[i]; if (y[i] > d) d = y[i] }
        print a - 3, b + 3, c - 3, d + 3 }' "$dir/tags.ini")
read -r end_x end_y < <(tail -1 "$dir/robot/trajectory_true.tum" | awk '{ print $2, $3 }')
PF_LOCALIZATION_PRELOAD=$plugin bash "$here/pf_localization.sh" "$dir" "$plugin" tags robot/obs.rawlog "$end_x" "$end_y" \
  particles_count=$particles init_PDF_min_x=$x0 init_PDF_max_x=$x1 init_PDF_min_y=$y0 init_PDF_max_y=$y1 \
  init_PDF_min_yaw_deg=-180 init_PDF_max_yaw_deg=180
log=$dir/tags_pf_localization.log
grep -q "scoreBeaconRanges *= *false" "$log" || { echo "FAIL: the tagMap was not loaded (plugin not preloaded?)"; exit 1; }
# The k-th "PDF estimation" (from 0) follows the k-th scan (the app runs no
# update at step 0); truth: TUM sensor poses, whose ground-plane part is the
# simulator's robot pose (docs/LOCALIZATION.md).
grep "PDF estimation" "$log" |
  sed -E 's/.*PDF estimation: \(([-0-9.]+),([-0-9.]+),([-0-9.]+)deg\).*/\1 \2 \3/' >"$dir/tags_pf_estimates.txt"
awk 'NR == FNR { x[NR] = $1; y[NR] = $2; yaw[NR] = $3; next }
  FNR > 1 && (FNR in x) { t = sqrt((x[FNR] - $2)^2 + (y[FNR] - $3)^2)
    r = yaw[FNR] - 2 * atan2($7, $8) * 45 / atan2(1, 1); while (r > 180) r -= 360; while (r < -180) r += 360
    printf "%d %.4f %.3f\n", FNR - 1, t, (r < 0 ? -r : r) }' "$dir/tags_pf_estimates.txt" "$dir/robot/trajectory_true.tum" \
  >"$dir/tags_pf_errors.txt"
awk -v from=$from -v max_step=$max_step -v max_t=$max_t -v max_r=$max_r -v n_truth="$(wc -l <"$dir/robot/trajectory_true.tum")" '
  { step[NR] = $1; t[NR] = $2; r[NR] = $3 }
  END {
    conv = -1; for (i = NR; i >= 1 && t[i] <= 0.3 && r[i] <= 10; i--) conv = step[i]
    for (i = 1; i <= NR; i++) if (step[i] >= from) { st += t[i]^2; sr += r[i]^2; m++; if (t[i] > mx) mx = t[i] }
    rt = m ? sqrt(st / m) : -1; rr = m ? sqrt(sr / m) : -1
    printf "stock pf-localization with tag poses: %d steps scored of %d scans, converged at step %d; from step %d: rmse_translation_m=%.4f rmse_rotation_deg=%.3f max_translation_m=%.4f\n",
      NR, n_truth, conv, from, rt, rr, mx
    ok = NR == n_truth - 1 && conv >= 0 && conv <= max_step && rt >= 0 && rt <= max_t && rr <= max_r
    if (!ok) printf "FAIL: needs every scan scored, converged by step %d, rmse <= %g m and <= %g deg\n", max_step, max_t, max_r
    exit !ok }' "$dir/tags_pf_errors.txt"
