#!/usr/bin/env bash
# Runs `acute mesh --method refine` over the classic domains and prints the meshcheck table
# (vertices, min angle, free min angle = away from forced corners, max angle, time).
# Usage: scripts/refine_table.sh [ACUTE_BIN] [MIN_ANGLE] [extra acute mesh options...]
#   env: DOMAINS (default ../shared/domains/classic/*.poly), OUT (default /tmp/refine-table)
# Exit 1 when a run fails, meshcheck rejects a mesh, or the free min angle is below MIN_ANGLE.
set -u
here=$(cd "$(dirname "$0")" && pwd)
acute=${1:-$here/../build/bin/acute}
min=${2:-30}
shift $(( $# > 2 ? 2 : $# ))
meshcheck=$here/../../shared/tools/meshcheck
out=${OUT:-/tmp/refine-table}
mkdir -p "$out"
status=0
printf '| domain | meshcheck | V | T | min | free min | max | below min (free) | s |\n|---|---|---|---|---|---|---|---|---|\n'
for d in ${DOMAINS:-$here/../../shared/domains/classic/*.poly}; do
  name=$(basename "$d" .poly)
  extra=(); check_domain=(--domain "$d")
  if [ "$name" = box ]; then extra=(--convex-hull); check_domain=(); fi
  t0=$(date +%s.%N)
  if ! "$acute" mesh "$d" -o "$out/$name.off" --method refine --min-angle "$min" -q "${extra[@]}" "$@" 2> "$out/$name.err"; then
    printf '| %s | run failed: %s |\n' "$name" "$(head -1 "$out/$name.err")"; status=1; continue
  fi
  t1=$(date +%s.%N)
  json=$(python3 "$meshcheck" "$out/$name.off" "${check_domain[@]}" --tolerance 1e-10 --json --min-angle "$min" --max-angle 180)
  row=$(JSON="$json" NAME="$name" MIN="$min" SECS="$(echo "$t1 - $t0" | bc)" python3 - <<'PY'
import json, os
j = json.loads(os.environ["JSON"]); q = j.get("quality") or {}; m = float(os.environ["MIN"])
f = lambda x: "-" if x is None else (f"{x:.3f}" if isinstance(x, float) else str(x))
fm = q.get("free_min_angle")
bad = j["exit_code"] != 0 or (fm is not None and fm < m - 1e-9)  # meshcheck's angle tolerance
print(f"| {os.environ['NAME']} | {j['exit_code']} | {q.get('n_vertices')} | {q.get('n_triangles')} | {f(q.get('min_angle'))} | {f(fm)} | "
      f"{f(q.get('max_angle'))} | {q.get('n_below_min_free')} | {float(os.environ['SECS']):.2f} |" + (" FAIL" if bad else ""))
PY
)
  echo "$row"
  case "$row" in *FAIL) status=1 ;; esac
done
exit $status
