#!/usr/bin/env bash
# Output paths: an unwritable one is reported before any long computation, a
# missing folder is created, a folder given as a file name is refused.
source "$(dirname "$0")/lib.sh"
SCENE=$(dirname "$0")/one_tag.yaml
: >"$WORK/a_file"

CASE=simulate-into-missing-folder
CASES=$((CASES + 1))
run_tagmap simulate "$SCENE" --out "$WORK/new/deeper/sim"
[ "$STATUS" -eq 0 ] || fail "exit status $STATUS: $ERR"
for f in map.pcd ground_truth.json; do
	[ -s "$WORK/new/deeper/sim/$f" ] || fail "$f not written"
done
MAP=$WORK/new/deeper/sim/map.pcd

CASE=detect-into-missing-folder
CASES=$((CASES + 1))
run_tagmap detect "$MAP" --quiet --json "$WORK/out2/a/b/tags.json"
[ "$STATUS" -eq 0 ] || fail "exit status $STATUS: $ERR"
grep -q '"tags": \[' "$WORK/out2/a/b/tags.json" 2>/dev/null || fail "result not written into the created folder"

# An unwritable output must fail before the map is even read: with a missing
# input, the error must still be about the output.
CASE=detect-output-under-a-file
expect_detect_rejects_output() {
	CASES=$((CASES + 1))
	run_tagmap detect "$WORK/missing_input.pcd" --quiet --json "$1"
	check_one_line_error "$2"
}
expect_detect_rejects_output "$WORK/a_file/tags.json" "a_file/tags\.json: cannot create folder"
CASE=detect-output-is-folder
expect_detect_rejects_output "$WORK/new" "new: is a directory"
CASE=detect-output-in-proc
expect_detect_rejects_output "/proc/self/tags.json" "/proc/self/tags\.json: "
CASE=detect-output-where-no-file-can-be-made
expect_detect_rejects_output "/proc/tags.json" "/proc/tags\.json: (cannot create a file in folder|folder) /proc"
CASE=detect-output-empty
expect_detect_rejects_output "" "output path is empty"

# Every output of detect is checked up front, not only --json: a bad
# --landmarks/--ini/... path fails before the map is read or --json written.
for opt in --landmarks --tagmap --ini --rawlog --3dscene --report; do
	CASE=detect$opt-under-a-file
	CASES=$((CASES + 1))
	rm -f "$WORK/first.json"
	run_tagmap detect "$MAP" --quiet --json "$WORK/first.json" "$opt" "$WORK/a_file/out"
	check_one_line_error "a_file/out"
	[ ! -e "$WORK/first.json" ] || fail "--json was written although $opt cannot be"
done

CASE=simulate-output-under-a-file
CASES=$((CASES + 1))
start=$(date +%s)
# --points makes the simulation long (minutes): only an early check is fast.
run_tagmap simulate "$SCENE" --out "$WORK/a_file/sim" --points 50000000
check_one_line_error "a_file/sim.*cannot create folder"
[ $(($(date +%s) - start)) -lt 20 ] || fail "the unwritable output was reported only after simulating"

finish
