#!/usr/bin/env bash
# Malformed scene files and bad flags for `tagmap simulate`: one line naming
# the file and the key (or line), non-zero status, no output written.
source "$(dirname "$0")/lib.sh"
S=$WORK/scenes
mkdir -p "$S"
GOOD=$(dirname "$0")/one_tag.yaml

# scene_case NAME YAML PATTERN: writes the scene and expects it rejected.
scene_case() {
	CASE=scene-$1
	printf '%s\n' "$2" >"$S/$1.yaml"
	rm -rf "$WORK/sim"
	expect_rejects "$1\.yaml: .*$3" simulate "$S/$1.yaml" --out "$WORK/sim"
	[ -z "$(ls -A "$WORK/sim" 2>/dev/null)" ] || fail "output written: $(ls "$WORK/sim")"
}
# good_with SED_EXPR: the good scene with one edit.
good_with() { sed -e "$1" "$GOOD"; }

scene_case syntax "$(good_with 's/size: \[6, 3\]/size: [6, 3/')" "YAML"
scene_case tabs "$(printf 'name: x\nobjects:\n\t- {name: a}\n')" "YAML"
scene_case unknown-family "$(good_with 's/tag36h11/tag36h12/')" "tag36h12.*tag36h11"
scene_case negative-size "$(good_with 's/size: 0.3,/size: -0.3,/')" "size"
scene_case size-text "$(good_with 's/size: 0.3,/size: big,/')" "size"
scene_case zero-normal "$(good_with '0,/normal: \[-1, 0, 0\]/s//normal: [0, 0, 0]/')" "normal"
scene_case short-position "$(good_with 's/position: \[3, 0.4, 1.4\]/position: [3, 0.4]/')" "position"
scene_case no-sensors "$(good_with '/^sensors:/,/range_noise/d')" "sensor"
scene_case unknown-sensor "$(good_with 's/sensor: tls/sensor: nope/')" "nope"
scene_case huge-step-count "$(good_with 's/step_deg: \[0.08, 0.08\]/step_deg: [1e-9, 1e-9]/')" "step"
scene_case nan-position "$(good_with 's/position: \[3, 0.4, 1.4\]/position: [.nan, 0.4, 1.4]/')" "position"
scene_case not-a-map "- just a list" "map"
# libfyaml loops forever on this one (found by fuzz_scene).
scene_case not-utf8 "$(printf '%%\xff\xff ')" "line 1, column 2: not UTF-8"
scene_case empty "" "empty|map|name"

CASE=scene-missing
expect_rejects "nowhere\.yaml: " simulate "$S/nowhere.yaml" --out "$WORK/sim"
CASE=scene-bad-points
expect_rejects "--points" simulate "$GOOD" --out "$WORK/sim" --points -3
CASE=scene-bad-param
expect_rejects "--param" simulate "$GOOD" --out "$WORK/sim" --param noequals

# Not bad input: every --param given applies, not only the last one.
CASE=scene-two-params
sed -e 's/^name: one_tag$/name: one_tag\nparameters: {first_id: 1, second_id: 2}/' \
	-e 's/id: 3,/id: $first_id,/' -e 's/id: 7,/id: $second_id,/' "$GOOD" >"$S/two_params.yaml"
run_tagmap simulate "$S/two_params.yaml" --out "$WORK/params" --param first_id=5 --param second_id=9 --quiet
[ "$STATUS" -eq 0 ] || fail "simulate with two --param: status $STATUS: $ERR"
ids=$(grep -o '"id": *[0-9]*' "$WORK/params/ground_truth.json" 2>/dev/null | grep -o '[0-9]*$' | sort -nu | tr '\n' ' ')
[ "$ids" = "5 9 " ] || fail "tag ids '$ids', expected '5 9 ' (both --param applied)"
CASES=$((CASES + 1))

finish
