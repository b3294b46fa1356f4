#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan+UBSan) in ./build-fuzz and runs one for a given time.
# Usage: scripts/fuzz.sh TARGET SECONDS [libFuzzer args...]
#   TARGET: fuzz_poly | fuzz_cgshop | fuzz_mesh_reader | fuzz_cdt | fuzz_mesher | build (only build all)
#           | regress (replay tests/fuzz/regressions/TARGET-*: exit 1 if any still fails)
# The seed corpus tests/fuzz/corpus/TARGET is copied into build-fuzz/corpus/TARGET, which grows
# between runs; crashes, timeouts and leaks go to build-fuzz/artifacts/TARGET/.
# Reproduce a crash: build-fuzz/bin/TARGET FILE.   Needs clang++ and libclang-rt-14-dev.
# To look past known bugs: ACUTE_FUZZ_IGNORE='text1|text2' (findings containing a text are
# skipped), e.g. with ASAN_OPTIONS=allocator_may_return_null=1 and ACUTE_FUZZ_IGNORE=bad_alloc;
# or collect every crash with the libFuzzer args -fork=1 -ignore_crashes=1.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: scripts/fuzz.sh TARGET SECONDS [libFuzzer args...]}
seconds=${2:-60}
shift $(( $# >= 2 ? 2 : $# ))
dir=${FUZZ_BUILD_DIR:-build-fuzz}
jobs=${JOBS:-2}

if [ ! -f "$dir/CMakeCache.txt" ]; then
  CXX=${CXX:-clang++} cmake -S tests/fuzz -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
if [ "$target" = build ]; then
  cmake --build "$dir" -j"$jobs"
  exit 0
fi
if [ "$target" = regress ]; then
  # Replays tests/fuzz/regressions/<target>-<what> with its target (and the runs' time limit per
  # input): lists the ones still failing.
  cmake --build "$dir" -j"$jobs" >/dev/null
  bad=0
  for f in tests/fuzz/regressions/*; do
    t=$(basename "$f"); t=${t%%-*}
    # The runs' time limit per input (10 s): an input that hangs fails here too. libFuzzer's own
    # -timeout is not enforced on inputs given as files (a 23 s replay passed it), so coreutils'.
    if timeout 10 "$dir/bin/$t" "$f" >/dev/null 2>&1; then echo "fixed   $(basename "$f")"; else echo "FAILING $(basename "$f")"; bad=$((bad + 1)); fi
  done
  exit $(( bad > 0 ))
fi
cmake --build "$dir" -j"$jobs" --target "$target"

corpus="$dir/corpus/$target"
artifacts="$dir/artifacts/$target"
mkdir -p "$corpus" "$artifacts"
if [ -d "tests/fuzz/corpus/$target" ]; then cp -n "tests/fuzz/corpus/$target"/* "$corpus"/ 2>/dev/null || true; fi
case "$target" in
  fuzz_cdt) max_len=128 ;;
  fuzz_mesher) max_len=64 ;;
  *) max_len=8192 ;;
esac
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# A hang is a finding too: -timeout per input. RSS limit against runaway memory.
exec "$dir/bin/$target" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len="$max_len" -artifact_prefix="$artifacts/" -print_final_stats=1 "$@"
