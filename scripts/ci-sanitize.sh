#!/usr/bin/env bash
# Builds the unit tests, the tagmap binary and the fuzz-regression replays
# with AddressSanitizer + UndefinedBehaviorSanitizer (-DTAGMAP_SANITIZE=ON) in
# build-asan/ and runs them there, bad-input shell tests included. Left out:
# the MRPT GUI/app tests and the Chromium report test (external programs, not
# our code, and far too slow under ASan), and the long whole-pipeline runs
# (benchmarks, end-to-end localization, determinism, kill mid-run: minutes
# each under ASan), which the regular build covers; and the install test,
# which installs the whole tree while only the targets above are built here.
set -euo pipefail
cd "$(dirname "$0")/.."
B=build-asan
TARGETS=(
	test_core test_io test_sim_patterns test_sim_physics test_sim_drift test_sim_scene
	test_tag_decoder test_stages test_pipeline test_localize tagmap
	fuzz_pcd_replay fuzz_ply_replay fuzz_las_replay fuzz_lzf_replay fuzz_scene_replay fuzz_config_replay
)
EXCLUDE='_NOT_BUILT|^mrpt_|report_chromium|^bench_|^localize_|reliability_(determinism|kill_midrun)|^install_'

cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAGMAP_SANITIZE=ON >/dev/null
cmake --build "$B" -j"$(nproc)" --target "${TARGETS[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:check_initialization_order=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0}
# ASan reserves terabytes of address space: no cap on the CLI runs here.
export TAGMAP_RELIABILITY_VMEM_KB=unlimited
ctest --test-dir "$B" --output-on-failure -j"$(nproc)" -E "$EXCLUDE"
