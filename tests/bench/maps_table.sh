#!/usr/bin/env bash
# Detection table over a folder of maps with ground truth: every X.pcd (or
# .ply/.las) beside an X.gt.json (`tags` list in the result schema; a tag
# with "expected": false need not be found). Runs `tagmap detect` with its
# defaults (every family, any size) plus any extra arguments, scores it with
# `tagmap compare`, and prints one row per map: points, wall seconds, peak
# memory, required tags found, false tags by kind, and for maps with tags the
# mean position and roll/pitch/yaw errors; below a row, its false and missed tags.
#
#   tests/bench/maps_table.sh DIR [--tagmap build/bin/tagmap] [-- detect args...]
#
# A benchmark, not a test: it prints numbers and exits 0 even when tags are
# missed; the totals line says what a test would have asserted.
set -euo pipefail

dir=${1:?usage: maps_table.sh DIR [--tagmap BIN] [-- detect args...]}
shift
tagmap="$(cd "$(dirname "$0")/../.." && pwd)/build/bin/tagmap"
if [ "${1:-}" = --tagmap ]; then tagmap=$2; shift 2; fi
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
	"$tagmap" compare "$work/$name.json" "$truth" >"$work/cmp" 2>&1 || true
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
