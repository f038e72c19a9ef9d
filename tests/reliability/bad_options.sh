#!/usr/bin/env bash
# Bad flags and bad configuration files for `tagmap detect` and
# `tagmap config --dump`: one clear line, non-zero status, outputs untouched.
source "$(dirname "$0")/lib.sh"
C=$WORK/config
mkdir -p "$C"
# A valid map, so only the option under test can be wrong.
printf 'VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 1 5\n' >"$C/map.pcd"
MAP=$C/map.pcd

# detect_with_bad ARGS... -- PATTERN: like expect_detect_rejects, with flags.
detect_with_bad() {
	local args=() pattern
	while [ "$1" != "--" ]; do args+=("$1"); shift; done
	pattern=$2
	CASES=$((CASES + 1))
	rm -rf "$WORK/out"
	mkdir -p "$WORK/out"
	printf '{"tags": []}\n' >"$WORK/out/old.json"
	cp "$WORK/out/old.json" "$WORK/out/old.json.orig"
	run_tagmap detect "$MAP" --quiet --json "$WORK/out/old.json" "${args[@]}"
	check_one_line_error "$pattern"
	cmp -s "$WORK/out/old.json" "$WORK/out/old.json.orig" || fail "the existing output file was changed"
	run_tagmap detect "$MAP" --quiet --json "$WORK/out/new.json" "${args[@]}"
	check_one_line_error "$pattern"
	[ ! -e "$WORK/out/new.json" ] || fail "an output file was created"
}

CASE=unknown-family
detect_with_bad --family tag37h11 -- "tag37h11.*tag36h11.*aruco_4x4_50"
CASE=unknown-family-in-list
detect_with_bad --family tag36h11,aruco_9x9 -- "aruco_9x9.*tag36h11"
CASE=tag-size-zero
detect_with_bad --tag-size 0 -- "--tag-size"
CASE=tag-size-negative
detect_with_bad --tag-size -0.2 -- "--tag-size"
CASE=tag-size-text
detect_with_bad --tag-size big -- "--tag-size: 'big' is not a number"
CASE=tag-size-nan
detect_with_bad --tag-size nan -- "--tag-size"
CASE=viewpoints-missing
detect_with_bad --viewpoints "$C/nowhere.tum" -- "nowhere\.tum: cannot open"
CASE=viewpoints-empty
printf '# no pose\n' >"$C/empty.tum"
detect_with_bad --viewpoints "$C/empty.tum" -- "empty\.tum: no pose"
CASE=viewpoints-garbage
printf '0 1 2 x\n' >"$C/bad.tum"
detect_with_bad --viewpoints "$C/bad.tum" -- "bad\.tum: line 1"
CASE=viewpoints-in-another-frame
printf '0 512345 5123456 187 0 0 0 1\n' >"$C/utm.tum"  # UTM, while the map is local
detect_with_bad --viewpoints "$C/utm.tum" -- "utm\.tum: no sensor position within 1000 m of the map"
CASE=tag-size-absurd
detect_with_bad --tag-size 1e30 -- "--tag-size must be a positive length in metres, at most 10"
CASE=threads-zero
detect_with_bad --threads 0 -- "--threads"
CASE=threads-negative
detect_with_bad --threads -4 -- "--threads"
CASE=threads-text
detect_with_bad --threads many -- "--threads: 'many' is not an integer"
CASE=threads-huge
detect_with_bad --threads 99999999999999999999 -- "--threads"
CASE=unknown-option
detect_with_bad --frobnicate 1 -- "unknown option --frobnicate"

# config_case NAME YAML PATTERN: a configuration file that must be rejected,
# by detect and by config --dump alike.
config_case() {
	CASE=config-$1
	printf '%s\n' "$2" >"$C/$1.yaml"
	detect_with_bad --config "$C/$1.yaml" -- "$1\.yaml: .*$3"
	expect_rejects "$1\.yaml: .*$3" config --dump --config "$C/$1.yaml"
}
config_case tag-size-negative 'tag_size: -0.2' "tag_size"
config_case tag-size-in-millimetres 'tag_size: 164' "tag_size must be a length in metres up to 10"
config_case max-tag-size-absurd $'candidates:\n  max_tag_size: 1000' "candidates.max_tag_size must be at most 10"
config_case threshold-zero $'gradient:\n  threshold: 0' "gradient\.threshold"
config_case threshold-negative $'gradient:\n  threshold: -1' "gradient\.threshold"
config_case min-size-negative $'candidates:\n  min_tag_size: -0.1' "candidates\.min_tag_size"
config_case sizes-swapped $'candidates:\n  min_tag_size: 2\n  max_tag_size: 1' "max_tag_size"
config_case threads-negative 'threads: -2' "threads"
config_case threads-huge 'threads: 100000' "threads"
config_case min-points-negative $'clustering:\n  min_points: -5' "clustering\.min_points"
config_case iterations-negative $'refinement:\n  iterations: -1' "refinement\.iterations"
config_case unknown-key 'tag_sise: 0.2' "unknown key 'tag_sise' \(allowed: .*tag_size"
config_case unknown-section-key $'gradient:\n  treshold: 0.2' "unknown key 'gradient\.treshold' \(allowed: .*threshold"
config_case not-a-number 'tag_size: big' "tag_size"
config_case bad-family 'families: [tag36h11, tag99h99]' "tag99h99.*tag36h11"
config_case bad-variant 'image_variants: [raw, sharp]' "sharp"
config_case not-a-map '- tag_size' "map"
config_case section-not-map 'gradient: 3' "gradient"
config_case syntax-error $'gradient:\n  threshold: [0.3\n  min_neighbours: 6' "YAML"
config_case not-utf8 "$(printf '%%\x80')" "line 1, column 2: not UTF-8"
config_case tabs $'gradient:\n\tthreshold: 0.3' "YAML"

CASE=config-missing
detect_with_bad --config "$C/nowhere.yaml" -- "nowhere\.yaml: .*(No such file|not exist|cannot)"

CASE=config-is-directory
detect_with_bad --config "$C" -- "$C: "

finish
