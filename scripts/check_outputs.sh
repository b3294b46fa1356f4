#!/usr/bin/env bash
# Runs the independent referee ../shared/tools/meshcheck on
#  1. every mesh the tests wrote under BUILD/test-output that has a sibling NAME.meshcheck file holding
#     the meshcheck arguments for it (e.g. "--domain /path/in.poly --tolerance 1e-10");
#  2. the CLI on the shared domains (CDT of every classic domain and CG:SHOP instance, and the default
#     pipeline on the classic domains), when the CLI supports them;
#  3. `acute repair` of every shared mesh, with the bounds.
# Fails on any non-zero verdict. Usage: scripts/check_outputs.sh [BUILD_DIR]
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shared=../shared
meshcheck="python3 $shared/tools/meshcheck"
acute=$build/bin/acute
failures=0
checked=0

check() {  # check MESH ARGS...
  local mesh=$1; shift
  local out
  if ! out=$($meshcheck "$mesh" "$@" 2>&1); then
    echo "meshcheck FAILED: $mesh $*"
    echo "$out" | grep -iE "verdict|fail|error" | head -5
    failures=$((failures + 1))
  fi
  checked=$((checked + 1))
}

# 1. Meshes written by the tests.
while IFS= read -r -d '' spec; do
  mesh=${spec%.meshcheck}
  for ext in off obj ele; do [ -f "$mesh.$ext" ] && { read -r -a args < "$spec"; check "$mesh.$ext" "${args[@]}"; break; }; done
done < <(find "$build/test-output" -name '*.meshcheck' -print0 2>/dev/null)
echo "check_outputs: test meshes checked: $checked, failures: $failures"

# 2. The CLI on the shared domains.
out=$build/ci-output
mkdir -p "$out"
if [ -x "$acute" ] && "$acute" mesh --help 2>/dev/null | grep -q -- "--method"; then
  n_before=$checked
  for d in "$shared"/domains/classic/*.poly "$shared"/domains/cgshop2025/instances/*.json; do
    name=$(basename "${d%.*}")
    extra=(); [ "$name" = box ] && extra=(--convex-hull)
    if "$acute" mesh "$d" -o "$out/cdt_$name.off" --method cdt -q "${extra[@]}" 2>"$out/cdt_$name.err"; then
      [ "$name" = box ] || check "$out/cdt_$name.off" --domain "$d" --tolerance 1e-10
    else
      echo "acute mesh --method cdt FAILED on $d: $(head -1 "$out/cdt_$name.err")"; failures=$((failures + 1))
    fi
  done
  echo "check_outputs: CDT runs checked: $((checked - n_before)), failures so far: $failures"
fi

# 3. The default acute pipeline on the classic domains: every output must be valid and conforming
#    (meshcheck exit 0 or 1); how many meet [30, 90) is reported (the goal is all of them).
if [ -x "$acute" ]; then
  n_before=$checked; met=0; runs=0; dual_ok=0
  for d in "$shared"/domains/classic/*.poly; do
    name=$(basename "${d%.*}")
    extra=(); [ "$name" = box ] && extra=(--convex-hull)
    runs=$((runs + 1))
    timeout 600 "$acute" mesh "$d" -o "$out/acute_$name.off" --vertices 2000 --time-limit 60 --json \
      --dual "$out/acute_${name}_dual.vtu" "${extra[@]}" >"$out/acute_$name.json" 2>"$out/acute_$name.err"
    rc=$?
    if [ "$rc" -gt 1 ]; then
      echo "acute mesh FAILED (exit $rc) on $d: $(head -1 "$out/acute_$name.err")"; failures=$((failures + 1)); continue
    fi
    domain_args=(--domain "$d"); [ "$name" = box ] && domain_args=()
    python3 "$shared/tools/meshcheck" "$out/acute_$name.off" "${domain_args[@]}" --tolerance 1e-10 --min-angle 30 --max-angle 90 >/dev/null 2>&1
    mc=$?
    checked=$((checked + 1))
    if [ "$mc" -gt 1 ]; then echo "meshcheck: acute output of $name is INVALID (exit $mc)"; failures=$((failures + 1));
    elif [ "$mc" -eq 0 ]; then
      met=$((met + 1))
      # An acute mesh must have a well-centred dual: every circumcentre strictly inside (exact check).
      if python3 -c 'import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))["dual"]["well_centered"] else 1)' "$out/acute_$name.json"; then
        dual_ok=$((dual_ok + 1))
      else
        echo "dual: acute mesh of $name meets the bounds but its dual is not well-centred"; failures=$((failures + 1))
      fi
    fi
  done
  echo "check_outputs: acute pipeline: $met of $runs classic domains meet [30, 90) at ~2000 vertices (all outputs checked for validity); well-centred dual on $dual_ok of those $met"
fi

# 3b. `acute repair` on the meshes made by other software (shared/domains/meshes): each repaired
# mesh must conform to its input and meet [30, 90) (issue 6).
if [ -x "$acute" ] && [ -d "$shared/domains/meshes" ]; then
  repaired=0
  for m in "$shared"/domains/meshes/*.off "$shared"/domains/meshes/*.obj; do
    [ -f "$m" ] || continue
    name=$(basename "${m%.*}")
    "$acute" repair "$m" -o "$out/repair_$name.off" -q --time-limit 120 >/dev/null 2>&1
    check "$out/repair_$name.off" --domain "$m" --tolerance 1e-10 --min-angle 30 --max-angle 90
    repaired=$((repaired + 1))
  done
  echo "check_outputs: acute repair of $repaired shared meshes judged with [30, 90)"
fi

# 4. Our quality report against the referee's.
if [ -f scripts/compare_stats_meshcheck.sh ]; then
  bash scripts/compare_stats_meshcheck.sh --acute "$acute" || failures=$((failures + 1))
fi

echo "check_outputs: $((checked - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
