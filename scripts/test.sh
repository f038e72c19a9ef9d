#!/usr/bin/env bash
# The test command of the README and of CI: set up, build, run every test;
# then, unless TAGMAP_QUICK=1, the sanitizer build and the fuzzers
# (scripts/ci-sanitize.sh, scripts/ci-fuzz.sh; each in its own build dir).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "${TAGMAP_QUICK:-0}" != 1 ]; then
	bash scripts/ci-sanitize.sh
	bash scripts/ci-fuzz.sh
fi
