#!/usr/bin/env bash
# Detection table over a folder of maps with ground truth: every X.pcd (or
# .ply/.las) beside an X.gt.json (`tags` list in the result schema; a tag
# with "expected": false need not be found). Runs `tagmap detect` with its
# defaults (every family, any size) plus any extra arguments, scores it with
# `tagmap compare`, and prints one row per map: points, wall seconds, peak
# memory, required tags found, false tags by kind, and for maps with tags the
# mean position and roll/pitch/yaw errors; below a row, its false and missed tags.
# Then recall by the conditions the truth files record per tag (range,
# points per tag cell), when they do.
#
#   tests/bench/maps_table.sh DIR [--tagmap build/bin/tagmap] [--keep OUT] [-- detect args...]
#
# --keep OUT keeps each map's result (OUT/X.json) and its comparison with the
# per-tag conditions of the truth (OUT/X.cmp, `tagmap compare --conditions`).
#
# A benchmark, not a test: it prints numbers and exits 0 even when tags are
# missed; the totals line says what a test would have asserted.
set -euo pipefail

usage="usage: maps_table.sh DIR [--tagmap BIN] [--keep OUT] [-- detect args...]"
dir=${1:?$usage}
shift
tagmap="$(cd "$(dirname "$0")/../.." && pwd)/build/bin/tagmap"
keep=""
while [ $# -gt 0 ] && [ "$1" != -- ]; do
	case $1 in
	--tagmap) tagmap=$2; shift 2 ;;
	--keep) keep=$2; mkdir -p "$keep"; shift 2 ;;
	*) echo "maps_table: unknown option $1 ($usage)" >&2; exit 2 ;;
	esac
done
[ "${1:-}" = -- ] && shift
[ -x "$tagmap" ] || { echo "maps_table: no tagmap binary at $tagmap" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-26s %9s %7s %7s %6s %5s %5s %5s %5s %9s %7s %7s %7s\n' map points wall_s MB found false wrong dup miss pos_mm roll pitch yaw
tot_req=0 tot_found=0 tot_false=0 tot_wrong=0 tot_dup=0 tot_pts=0
for truth in "$dir"/*.gt.json; do
	name=$(basename "$truth" .gt.json)
	map=""
	for ext in pcd ply las; do [ -f "$dir/$name.$ext" ] && map="$dir/$name.$ext" && break; done
	[ -n "$map" ] || continue
	if ! /usr/bin/time -v -o "$work/time" "$tagmap" detect "$map" --json "$work/$name.json" "$@" \
		>"$work/out" 2>"$work/err"; then
		printf '%-26s detect failed: %s\n' "$name" "$(tail -1 "$work/err")"
		continue
	fi
	wall=$(awk -F': ' '/Elapsed \(wall clock\)/{n=split($2,a,":"); s=0; for(i=1;i<=n;i++) s=s*60+a[i]; printf "%.2f", s}' "$work/time")
	mb=$(awk -F': ' '/Maximum resident/{printf "%.0f", $2/1024}' "$work/time")
	points=$(cat "$work/out" "$work/err" | grep -oE 'read [0-9]+ points' | head -1 | grep -oE '[0-9]+' || true)
	points=${points:-?}
	"$tagmap" compare "$work/$name.json" "$truth" --conditions >"$work/cmp" 2>&1 || true
	grep -E '^conditions: ' "$work/cmp" | tail -n +2 >>"$work/conditions" || true
	[ -n "$keep" ] && cp "$work/$name.json" "$keep/$name.json" && cp "$work/cmp" "$keep/$name.cmp"
	summary=$(grep -E '^found ' "$work/cmp" | tail -1)
	found=$(echo "$summary" | awk '{print $2}')
	total=$(echo "$summary" | awk '{print $4}' | tr -d ,)
	missed=$(echo "$summary" | awk '{print $6}' | tr -d ,)
	false=$(echo "$summary" | awk '{print $8}')
	wrong=$(echo "$summary" | grep -oE 'wrong family/id [0-9]+' | grep -oE '[0-9]+$')
	dup=$(echo "$summary" | grep -oE 'duplicate [0-9]+' | grep -oE '[0-9]+$')
	errs=$(awk '$3=="yes"{n++; p+=sqrt($4*$4+$5*$5+$6*$6); r+=$7; q+=$8; y+=$9}
		END{if(n) printf "%9.2f %7.3f %7.3f %7.3f", 1000*p/n, r/n, q/n, y/n; else printf "%9s %7s %7s %7s", "-", "-", "-", "-"}' "$work/cmp")
	printf '%-26s %9s %7s %7s %6s %5s %5s %5s %5s %s\n' "$name" "$points" "$wall" "$mb" "$found/$total" \
		"$((false - wrong - dup))" "$wrong" "$dup" "$missed" "$errs"
	grep -E '^false detection' "$work/cmp" | sed 's/^/    /' || true
	awk '$3=="no"{printf "    missed %s %s\n", $1, $2}' "$work/cmp" || true
	tot_found=$((tot_found + found)) tot_req=$((tot_req + total)) tot_false=$((tot_false + false - wrong - dup))
	tot_wrong=$((tot_wrong + wrong)) tot_dup=$((tot_dup + dup))
	[ "$points" != "?" ] && tot_pts=$((tot_pts + points))
done
echo "total: $tot_pts points, found $tot_found of $tot_req true tags, false $tot_false, wrong family/id $tot_wrong, duplicate $tot_dup"

# Recall by condition: the truths' range_min and points_per_cell per tag
# (required tags only: a tag marked not expected is neither found nor missed).
[ -s "$work/conditions" ] && awk '
	function bin(v, edges, n,   i) { for (i = 1; i <= n; i++) if (v < edges[i]) return i; return n + 1 }
	BEGIN {
		nr = split("2 3 4 5 6 8 12", re, " "); np = split("2 4 8 16 32 64", pe, " ")
	}
	$4 == "yes" || $4 == "no" {
		if ($6 != "-") { b = bin($6, re, nr); rt[b]++; if ($4 == "yes") rf[b]++; anyr = 1 }
		if ($5 != "-") { b = bin($5, pe, np); pt[b]++; if ($4 == "yes") pf[b]++; anyp = 1 }
	}
	function table(title, edges, n, tot, fnd, unit,   i, lo, hi) {
		printf "recall by %s:", title
		for (i = 1; i <= n + 1; i++) {
			if (!tot[i]) continue
			lo = i == 1 ? 0 : edges[i - 1]
			if (i <= n) printf "  %s-%s%s %d/%d", lo, edges[i], unit, fnd[i], tot[i]
			else printf "  %s+%s %d/%d", lo, unit, fnd[i], tot[i]
		}
		printf "\n"
	}
	END {
		if (anyr) table("range", re, nr, rt, rf, " m")
		if (anyp) table("points per cell", pe, np, pt, pf, "")
	}' "$work/conditions"
exit 0
