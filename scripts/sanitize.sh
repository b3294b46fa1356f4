#!/usr/bin/env bash
# Builds libacute with AddressSanitizer + UndefinedBehaviorSanitizer in ./build-asan (Debug at -O1:
# assertions of Eigen/OpenMesh stay on, still fast enough for CI) and runs the whole test suite.
# Any sanitizer report aborts the test that triggered it. Extra arguments go to the configure step.
# Usage: scripts/sanitize.sh [cmake args...]
#   env: JOBS (default nproc), BUILD_DIR (build-asan), TEST_TIMEOUT (s per test, 300), CTEST_ARGS
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
dir=${BUILD_DIR:-build-asan}
start=$(date +%s)

cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
  -DLIBACUTE_SANITIZE=ON -DLIBACUTE_BUILD_BENCH=OFF "$@" >/dev/null
cmake --build "$dir" -j"$jobs"
built=$(date +%s)

# halt_on_error: first report fails the test; detect_leaks: leaks are bugs too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
# CTEST_ARGS: e.g. "-E AcutePipeline" to leave out tests too slow under ASan (default per-test
# timeout 300 s).
rc=0
# shellcheck disable=SC2086
ctest --test-dir "$dir" --output-on-failure -j"$jobs" --timeout "${TEST_TIMEOUT:-300}" ${CTEST_ARGS:-} || rc=$?
echo "sanitize: build $(( built - start )) s, tests $(( $(date +%s) - built )) s"
exit $rc
