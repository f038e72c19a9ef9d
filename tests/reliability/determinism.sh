#!/usr/bin/env bash
# The same map and parameters give a byte-identical result file whatever the
# number of threads.
source "$(dirname "$0")/lib.sh"
SCENE=$(dirname "$0")/one_tag.yaml

CASE=simulate
CASES=$((CASES + 1))
run_tagmap simulate "$SCENE" --out "$WORK/sim" --seed 7
[ "$STATUS" -eq 0 ] || { fail "simulate failed: $ERR"; finish; exit; }

for t in 1 2 3; do
	CASE=threads-$t
	CASES=$((CASES + 1))
	run_tagmap detect "$WORK/sim/map.pcd" --quiet --threads "$t" --json "$WORK/tags_$t.json"
	[ "$STATUS" -eq 0 ] || fail "exit status $STATUS: $ERR"
done
CASE=tags-found
grep -q '"family"' "$WORK/tags_1.json" || fail "no tag found, the comparison would prove little: $(cat "$WORK/tags_1.json")"
for t in 2 3; do
	CASE=compare-1-$t
	cmp "$WORK/tags_1.json" "$WORK/tags_$t.json" || fail "--threads 1 and --threads $t differ: $(diff "$WORK/tags_1.json" "$WORK/tags_$t.json" | head -5)"
done

finish
