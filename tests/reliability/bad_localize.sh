#!/usr/bin/env bash
# Bad flags and bad files for `tagmap observe` and `tagmap localize`: one
# clear line, non-zero status, and an existing output file left untouched.
source "$(dirname "$0")/lib.sh"
L=$WORK/loc
mkdir -p "$L"
# Valid inputs, so only the thing under test is wrong: one simulated scan as
# a rawlog, the same after `observe`, and the scene's truth as the tag map.
run_tagmap simulate "$(dirname "$0")/one_tag.yaml" --out "$L/sim" --rawlog "$L/scans.rawlog" --quiet
[ "$STATUS" -eq 0 ] || { CASE=setup; fail "simulate failed: $ERR"; finish; exit; }
run_tagmap observe "$L/scans.rawlog" "$L/obs.rawlog" --quiet
[ "$STATUS" -eq 0 ] || { CASE=setup; fail "observe failed: $ERR"; finish; exit; }
MAP=$L/sim/ground_truth.json OBS=$L/obs.rawlog

CASE=localize-valid
CASES=$((CASES + 1))
run_tagmap localize --map "$MAP" --rawlog "$OBS" --method direct --out "$L/ok.tum" --quiet
[ "$STATUS" -eq 0 ] && [ -s "$L/ok.tum" ] || fail "a valid run failed ($STATUS): $ERR"

OUT=$L/out/previous.tum
# localize_rejects PATTERN ARGS...: `tagmap localize ARGS... --out OUT` fails
# cleanly and OUT (a previous result) keeps its bytes. --quiet, as every
# other driver here: on a loaded machine a stage that runs 2 s before the
# error prints a progress line, and the error is then not the only line.
localize_rejects() {
	local pattern=$1
	shift
	mkdir -p "$L/out"
	printf '0 1 2 3 0 0 0 1\n' >"$OUT"
	cp "$OUT" "$OUT.orig"
	expect_rejects "$pattern" localize "$@" --out "$OUT" --quiet
	cmp -s "$OUT" "$OUT.orig" || fail "the previous output was changed"
	[ -z "$(find "$L/out" -name '*.tmp*')" ] || fail "temporary file left behind"
}

CASE=method-unknown
localize_rejects "--method must be pf or direct" --map "$MAP" --rawlog "$OBS" --method icp
CASE=particles-text
localize_rejects "--particles: 'many' is not an integer" --map "$MAP" --rawlog "$OBS" --method pf --particles many
CASE=particles-too-few
localize_rejects "--particles must be between" --map "$MAP" --rawlog "$OBS" --method pf --particles 10
CASE=particles-absurd
localize_rejects "--particles must be between" --map "$MAP" --rawlog "$OBS" --method pf --particles 99999999999
CASE=seed-negative
localize_rejects "--seed must be between" --map "$MAP" --rawlog "$OBS" --method pf --seed -1
CASE=seed-too-big
localize_rejects "--seed must be between" --map "$MAP" --rawlog "$OBS" --method pf --seed 4294967296
CASE=model-unknown
localize_rejects "--model must be poses or ranges" --map "$MAP" --rawlog "$OBS" --method pf --model icp
CASE=model-for-direct
localize_rejects "--model and --no-odometry are for --method pf" --map "$MAP" --rawlog "$OBS" --method direct --model ranges
CASE=no-odometry-for-direct
localize_rejects "--model and --no-odometry are for --method pf" --map "$MAP" --rawlog "$OBS" --method direct --no-odometry
CASE=errors-without-truth
localize_rejects "--errors needs --truth" --map "$MAP" --rawlog "$OBS" --method pf --errors "$L/e.json"
CASE=map-missing
localize_rejects "nowhere\.json" --map "$L/nowhere.json" --rawlog "$OBS" --method direct
CASE=map-not-json
localize_rejects "obs\.rawlog: " --map "$OBS" --rawlog "$OBS" --method direct
CASE=map-without-tags
printf '{"tags": []}\n' >"$L/empty.json"
localize_rejects "empty\.json: .*no tags" --map "$L/empty.json" --rawlog "$OBS" --method direct
CASE=rawlog-missing
localize_rejects "nowhere\.rawlog" --map "$MAP" --rawlog "$L/nowhere.rawlog" --method direct
CASE=rawlog-junk
localize_rejects "ground_truth\.json: .*rawlog" --map "$MAP" --rawlog "$MAP" --method direct
CASE=rawlog-not-observed
localize_rejects "scans\.rawlog: .*tagmap observe" --map "$MAP" --rawlog "$L/scans.rawlog" --method direct
CASE=truth-malformed
printf '0.0 1 2 3 0 0 0 1\n0.1 1 2 oops 0 0 0 1\n' >"$L/bad.tum"
localize_rejects "bad\.tum: .*line 2" --map "$MAP" --rawlog "$OBS" --method direct --truth "$L/bad.tum"
CASE=output-under-a-file
printf 'x' >"$L/a_file"
expect_rejects "a_file/t\.tum" localize --map "$MAP" --rawlog "$OBS" --method direct --out "$L/a_file/t.tum"

# observe_rejects PATTERN IN [ARGS...]: `tagmap observe IN OUT ARGS...` fails
# cleanly and OUT (a previous rawlog) keeps its bytes.
observe_rejects() {
	local pattern=$1 in=$2
	shift 2
	cp "$OBS" "$L/out/previous.rawlog"
	expect_rejects "$pattern" observe "$in" "$L/out/previous.rawlog" --quiet "$@"
	cmp -s "$L/out/previous.rawlog" "$OBS" || fail "the previous output was changed"
}
CASE=observe-missing-input
observe_rejects "nowhere\.rawlog" "$L/nowhere.rawlog"
CASE=observe-junk-input
observe_rejects "ground_truth\.json: .*rawlog" "$MAP"
CASE=observe-bad-threads
observe_rejects "--threads" "$L/scans.rawlog" --threads 0
CASE=observe-bad-window
observe_rejects "--window must be 1-100" "$L/scans.rawlog" --window 0
CASE=observe-max-window-not-above-window
observe_rejects "--max-window must be above --window" "$L/scans.rawlog" --window 3 --max-window 3
CASE=observe-max-window-on-single-scans
observe_rejects "--max-window must be above --window \\(2 or more\\)" "$L/scans.rawlog" --max-window 5
CASE=observe-both-paths
observe_rejects "--sensor-view or --map-path, not both" "$L/scans.rawlog" --sensor-view --map-path
CASE=observe-bad-family
observe_rejects "tag37h11" "$L/scans.rawlog" --family tag37h11
CASE=observe-output-under-a-file
expect_rejects "a_file/o\.rawlog" observe "$L/scans.rawlog" "$L/a_file/o.rawlog" --quiet

finish
