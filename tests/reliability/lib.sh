# Helpers for the reliability scripts, which run the real `tagmap` binary on
# bad input and check the contract of docs/RESULT_FORMAT.md: one stderr line
# naming the file and the place, a non-zero status that is not a signal, and
# no output file created or changed. Sourced, not run.
# Usage: TAGMAP=/path/to/tagmap bash SCRIPT.sh
set -uo pipefail
: "${TAGMAP:?set TAGMAP to the tagmap binary}"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/tagmap-reliability.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
FAILS=0
CASES=0
# Bad input must fail at once; a minute means a hang.
LIMIT_SECONDS=${TAGMAP_RELIABILITY_TIMEOUT:-60}
# A header claiming 10^12 points must not make tagmap allocate for them:
# the address space is capped (KiB) for every run.
LIMIT_VMEM_KB=${TAGMAP_RELIABILITY_VMEM_KB:-8000000}

fail() {
	echo "FAIL [$CASE]: $*" >&2
	FAILS=$((FAILS + 1))
}

# run_tagmap ARGS...: runs tagmap with the limits; sets STATUS, ERR (stderr
# text) and ERR_LINES.
run_tagmap() {
	(ulimit -v "$LIMIT_VMEM_KB" 2>/dev/null; exec timeout -s KILL "$LIMIT_SECONDS" "$TAGMAP" "$@") \
		>"$WORK/stdout" 2>"$WORK/stderr"
	STATUS=$?
	ERR=$(cat "$WORK/stderr")
	ERR_LINES=$(grep -c '' "$WORK/stderr")
}

# check_one_line_error PATTERN...: the last run failed cleanly and its one
# stderr line matches every extended regex given (file name, place, what).
check_one_line_error() {
	if [ "$STATUS" -eq 0 ]; then fail "exit status 0, expected an error"; fi
	if [ "$STATUS" -ge 124 ]; then fail "exit status $STATUS: killed, timed out or crashed"; fi
	if [ "$ERR_LINES" -ne 1 ]; then fail "$ERR_LINES stderr lines, expected 1: $ERR"; fi
	local p
	for p in "$@"; do
		grep -Eq -- "$p" <<<"$ERR" || fail "stderr does not match /$p/: $ERR"
	done
}

# expect_detect_rejects INPUT PATTERN...: `tagmap detect INPUT` fails cleanly,
# once with a fresh output path (which must not appear) and once over an
# existing result file (which must stay byte-identical).
expect_detect_rejects() {
	local input=$1
	shift
	CASES=$((CASES + 1))
	rm -rf "$WORK/out"
	run_tagmap detect "$input" --json "$WORK/out/new.json" --quiet
	check_one_line_error "$@"
	[ ! -e "$WORK/out/new.json" ] || fail "an output file was created"
	mkdir -p "$WORK/out"
	printf '{"tags": [], "note": "previous result"}\n' >"$WORK/out/old.json"
	cp "$WORK/out/old.json" "$WORK/out/old.json.orig"
	run_tagmap detect "$input" --json "$WORK/out/old.json" --quiet
	check_one_line_error "$@"
	cmp -s "$WORK/out/old.json" "$WORK/out/old.json.orig" || fail "the existing output file was changed"
	leftovers=$(find "$WORK/out" -name '*.tmp*' | head -1)
	[ -z "$leftovers" ] || fail "temporary file left behind: $leftovers"
}

# expect_detect_accepts INPUT TAGS_PATTERN [ARGS...]: exit 0 and a result file
# whose text matches TAGS_PATTERN.
expect_detect_accepts() {
	local input=$1 pattern=$2
	shift 2
	CASES=$((CASES + 1))
	rm -rf "$WORK/out"
	run_tagmap detect "$input" --json "$WORK/out/ok.json" "$@"
	[ "$STATUS" -eq 0 ] || fail "exit status $STATUS: $ERR"
	grep -Eq -- "$pattern" "$WORK/out/ok.json" 2>/dev/null || fail "result does not match /$pattern/: $(cat "$WORK/out/ok.json" 2>&1)"
}

# expect_rejects PATTERN ARGS...: `tagmap ARGS...` fails cleanly with a
# stderr line matching PATTERN (for commands other than detect).
expect_rejects() {
	local pattern=$1
	shift
	CASES=$((CASES + 1))
	run_tagmap "$@"
	check_one_line_error "$pattern"
}

finish() {
	echo "$(basename "$0"): $CASES cases, $FAILS failures"
	[ "$FAILS" -eq 0 ]
}
