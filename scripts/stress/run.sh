#!/usr/bin/env bash
# Stress run: generates N random domains (scripts/stress/gen_domain.py, seeds FIRST..FIRST+N-1),
# meshes each with `acute mesh D -o OUT --method METHOD -q` under a timeout, and judges every
# output with ../shared/tools/meshcheck --tolerance 1e-10 (+ --min-angle 30 --max-angle 90 for
# method acute). Prints the pass rate and the failing seeds with the reason.
# Usage: scripts/stress/run.sh N METHOD [FIRST_SEED]
#   env: ACUTE (default build/bin/acute), TIMEOUT (seconds per run, default 120),
#        OUT (work directory, default build-stress/METHOD), EXTRA (more `acute mesh` arguments),
#        MESHCHECK (default ../shared/tools/meshcheck), BUDGET (seconds: start no new domain after that; the summary counts the ones run)
# OUT/log.txt: one line per seed (seed, ok | bounds | INVALID | ERROR, seconds); OUT/failing.txt:
# the failing seeds with the reason.
# Exit status 1 when any domain fails validity (or, for acute, the bounds).
set -uo pipefail
cd "$(dirname "$0")/../.."
n=${1:?usage: scripts/stress/run.sh N METHOD [FIRST_SEED]}
method=${2:?usage: scripts/stress/run.sh N METHOD [FIRST_SEED]}
first=${3:-1}
acute=${ACUTE:-build/bin/acute}
timeout_s=${TIMEOUT:-120}
out=${OUT:-build-stress/$method}
meshcheck=${MESHCHECK:-../shared/tools/meshcheck}
[ -x "$acute" ] || { echo "stress: $acute not found (build it first)" >&2; exit 3; }
[ -f "$meshcheck" ] || { echo "stress: $meshcheck not found" >&2; exit 3; }
mkdir -p "$out"
bounds=()
[ "$method" = acute ] && bounds=(--min-angle 30 --max-angle 90)

pass=0 valid=0 fail=0
failures=()
start=$(date +%s)
run=0
for (( seed = first; seed < first + n; seed++ )); do
  if [ -n "${BUDGET:-}" ] && [ $(( $(date +%s) - start )) -ge "$BUDGET" ]; then break; fi
  run=$((run + 1))
  d="$out/s$seed.poly"
  m="$out/s$seed.off"
  rm -f "$m"
  if ! python3 scripts/stress/gen_domain.py "$seed" "$d"; then
    failures+=("$seed: generator failed"); fail=$((fail + 1)); echo "$seed ERROR" >>"$out/log.txt"; continue
  fi
  t0=$(date +%s.%N)
  # shellcheck disable=SC2086
  timeout -k 5 "$timeout_s" "$acute" mesh "$d" -o "$m" --method "$method" -q ${EXTRA:-} 2>"$out/s$seed.err"
  rc=$?
  secs=$(echo "$(date +%s.%N) - $t0" | bc)
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    failures+=("$seed: timeout after ${timeout_s}s"); fail=$((fail + 1)); echo "$seed ERROR" >>"$out/log.txt"; continue
  fi
  if [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
    failures+=("$seed: acute exit $rc: $(head -c 300 "$out/s$seed.err" | head -1)"); fail=$((fail + 1)); echo "$seed ERROR" >>"$out/log.txt"; continue
  fi
  if [ ! -f "$m" ]; then
    failures+=("$seed: acute exit $rc but no output"); fail=$((fail + 1)); echo "$seed ERROR" >>"$out/log.txt"; continue
  fi
  report=$(python3 "$meshcheck" "$m" --domain "$d" --tolerance 1e-10 "${bounds[@]}" 2>&1)
  mc=$?
  if [ $mc -eq 0 ]; then
    pass=$((pass + 1)); valid=$((valid + 1))
  elif [ $mc -eq 1 ]; then
    valid=$((valid + 1))
    failures+=("$seed: bounds not met ($(echo "$report" | grep -m1 -E '^ +min angle' | tr -s ' '))"); fail=$((fail + 1))
  else
    why=$(echo "$report" | grep -m2 -E '^ +[a-z].* fail ' | tr -s ' ' | tr '\n' ';' | head -c 400)
    failures+=("$seed: meshcheck exit $mc: ${why:-$(echo "$report" | tail -1 | head -c 300)}")
    fail=$((fail + 1))
  fi
  printf '%s %s %.2fs\n' "$seed" "$([ $mc -eq 0 ] && echo ok || { [ $mc -eq 1 ] && echo bounds || echo INVALID; })" "$secs" >>"$out/log.txt"
done
elapsed=$(( $(date +%s) - start ))
echo "stress $method: $pass/$run passed, $valid/$run valid meshes, $fail failing ($elapsed s, seeds $first..$((first + run - 1)))"
: >"$out/failing.txt"
for f in "${failures[@]}"; do echo "  seed $f"; echo "$f" >>"$out/failing.txt"; done
[ $fail -eq 0 ]
