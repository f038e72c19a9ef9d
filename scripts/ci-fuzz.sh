#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/) with clang, ASan and UBSan in
# build-fuzz/ and runs each for TAGMAP_FUZZ_SECONDS (default 60) from its seed
# corpus. Fails on any crash, leak, timeout or sanitizer report; the input
# that caused it is saved under build-fuzz/findings/<target>/ - fix the bug,
# then copy the input to tests/fuzz/regressions/<target>/ so ctest replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${TAGMAP_FUZZ_SECONDS:-60}
TARGETS=(${TAGMAP_FUZZ_TARGETS:-pcd ply las lzf scene config})
B=build-fuzz
SAN="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# tagmap_warnings() has GCC-only options; clang need not list them.
QUIET="-Wno-unknown-warning-option"

CC=clang CXX=clang++ cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAGMAP_FUZZ=ON \
	-DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link $SAN $QUIET" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $SAN $QUIET" \
	-DCMAKE_EXE_LINKER_FLAGS="$SAN" -DCMAKE_SHARED_LINKER_FLAGS="$SAN" >/dev/null
cmake --build "$B" -j"$(nproc)" --target "${TARGETS[@]/#/fuzz_}"

# Leaks are checked; tests/fuzz/lsan.supp lists the third-party ones we
# cannot fix (each with its reason).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0}
status=0
for t in "${TARGETS[@]}"; do
	work=$B/corpus/$t findings=$B/findings/$t
	mkdir -p "$work" "$findings"
	# The working corpus grows across runs (kept in build-fuzz/); the seeds
	# in the repository are read-only input.
	log=$B/fuzz_$t.log
	# MRPT's YAML parser leaks on every syntax error (lsan.supp), which makes
	# libFuzzer run a full leak scan after nearly every input: 30 instead of
	# thousands of inputs a second. The YAML targets check leaks at exit only.
	# For the same reason their RSS creeps up over a run (the leaked parser
	# state of every syntax error adds up: 2.4 GB after ~45 s on a grown
	# corpus); the RSS cap for them is raised, the per-allocation cap is not.
	leaks=1 rss=2048
	case $t in scene | config) leaks=0 rss=6144 ;; esac
	echo "ci-fuzz: $t for ${SECONDS_PER_TARGET} s"
	if "$B/bin/fuzz_$t" "$work" "tests/fuzz/corpus/$t" -max_total_time="$SECONDS_PER_TARGET" \
		-detect_leaks=$leaks -rss_limit_mb=$rss -malloc_limit_mb=1024 -timeout=10 -max_len=8192 -print_final_stats=1 \
		-artifact_prefix="$findings/" >"$log" 2>&1; then
		echo "ci-fuzz: $t ok, $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') executions"
	else
		status=1
		echo "ci-fuzz: $t FAILED; the input is in $findings/, the report in $log:"
		grep -E 'ERROR|ALARM|runtime error|SUMMARY|Test unit written' "$log" | head -20 || true
	fi
done
exit $status
