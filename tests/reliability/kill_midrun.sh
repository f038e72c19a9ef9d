#!/usr/bin/env bash
# Nothing lost: `tagmap detect` killed with SIGKILL at any moment leaves the
# previous result file byte-identical (or, once finished, the complete new
# one), never a truncated file under the final name.
source "$(dirname "$0")/lib.sh"
SCENE=$(dirname "$0")/one_tag.yaml
# Dense enough that detection takes seconds, so kills land mid-computation.
POINTS=${TAGMAP_KILL_TEST_POINTS:-1500000}

CASE=simulate
CASES=$((CASES + 1))
run_tagmap simulate "$SCENE" --out "$WORK/sim" --points "$POINTS"
[ "$STATUS" -eq 0 ] || { fail "simulate failed: $ERR"; finish; exit; }

CASE=reference-run
CASES=$((CASES + 1))
start=$(date +%s%N)
run_tagmap detect "$WORK/sim/map.pcd" --quiet --json "$WORK/reference.json"
runtime_ms=$((($(date +%s%N) - start) / 1000000))
[ "$STATUS" -eq 0 ] || fail "exit status $STATUS: $ERR"
echo "detection takes $runtime_ms ms"

printf '{"tags": [], "note": "the previous result, must survive"}\n' >"$WORK/previous.json"
# Kill at a spread of moments: reading, mid-pipeline, near the end.
for percent in 5 25 50 75 95; do
	CASE=kill-at-$percent%
	CASES=$((CASES + 1))
	rm -rf "$WORK/out"
	mkdir -p "$WORK/out"
	cp "$WORK/previous.json" "$WORK/out/tags.json"
	"$TAGMAP" detect "$WORK/sim/map.pcd" --quiet --json "$WORK/out/tags.json" 2>/dev/null &
	pid=$!
	sleep "$(awk -v ms="$runtime_ms" -v p="$percent" 'BEGIN { printf "%.3f", ms * p / 100000 }')"
	kill -KILL "$pid" 2>/dev/null
	wait "$pid" 2>/dev/null
	if cmp -s "$WORK/out/tags.json" "$WORK/previous.json"; then
		:
	elif cmp -s "$WORK/out/tags.json" "$WORK/reference.json"; then
		echo "$CASE: the run had already finished"
	else
		fail "tags.json is neither the previous nor the complete new result: $(head -c 200 "$WORK/out/tags.json")"
	fi
	# A leftover temporary file is harmless, but it must never carry the
	# final name or look like a result to globbing tools.
	find "$WORK/out" -name 'tags.json*' ! -name tags.json ! -name 'tags.json.tmp-*' | grep . && fail "unexpected file next to the result"
done

finish
