#!/usr/bin/env bash
# Cross-checks `acute stats --json` against the independent referee `meshcheck --json`.
#  1. Every mesh (.off .obj .ele) of MESH_DIR: min/max angle within 1e-9 degrees; identical counts
#     (vertices, triangles, below min, above max, at max, right, obtuse, max violations,
#     histogram); means, std, Q and percentages within 1e-9 relative. When the mesh's stem (up to
#     the first dot) names a .poly of the domains folder, also with that domain (Steiner points,
#     forced corners, free triangles, free min angle).
#  2. Every .poly of the domains folder (and with --cgshop DIR every CG:SHOP .json there): forced
#     corners and Steiner count, which depend on the domain only (measured on a fixed small mesh).
# Exit 0 when everything agrees, 1 on any mismatch, 2 on a usage or tool error.
#
#   scripts/compare_stats_meshcheck.sh [MESH_DIR] [--acute BIN] [--meshcheck FILE] [--domains DIR]
#                                      [--cgshop DIR]
#
# Defaults (relative to the repository root): MESH_DIR ../shared/domains/meshes, BIN
# build/bin/acute, FILE ../shared/tools/meshcheck, DIR ../shared/domains/classic; no CG:SHOP pass
# (../shared/domains/cgshop2025/instances, 150 files, takes about 90 s).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mesh_dir="$root/../shared/domains/meshes"
acute="$root/build/bin/acute"
meshcheck="$root/../shared/tools/meshcheck"
domains="$root/../shared/domains/classic"
cgshop=""
while [ $# -gt 0 ]; do
  case "$1" in
    --acute) acute="$2"; shift 2 ;;
    --meshcheck) meshcheck="$2"; shift 2 ;;
    --domains) domains="$2"; shift 2 ;;
    --cgshop) cgshop="$2"; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    -*) echo "compare_stats_meshcheck: unknown option $1" >&2; exit 2 ;;
    *) mesh_dir="$1"; shift ;;
  esac
done
[ -x "$acute" ] || { echo "compare_stats_meshcheck: no acute binary at $acute (build first)" >&2; exit 2; }
[ -f "$meshcheck" ] || { echo "compare_stats_meshcheck: no meshcheck at $meshcheck" >&2; exit 2; }
[ -d "$mesh_dir" ] || { echo "compare_stats_meshcheck: no folder $mesh_dir" >&2; exit 2; }

# The comparison: argv = acute.json meshcheck.json label mode(mesh|domain) with_domain(0|1).
read -r -d '' compare_py <<'EOF' || true
import json, sys
a = json.load(open(sys.argv[1]))
m = json.load(open(sys.argv[2]))["quality"]
label, mode, with_domain = sys.argv[3], sys.argv[4], sys.argv[5] == "1"
exact, close_abs, close_rel = [], [], []
if mode == "mesh":
    exact = ["n_vertices", "n_triangles", "n_below_min", "n_above_max", "n_at_max", "n_right",
             "n_obtuse", "n_max_violations", "histogram"]
    close_abs = ["min_angle", "max_angle"]
    close_rel = ["mean_min_angle", "std_min_angle", "mean_max_angle", "std_max_angle", "q_min",
                 "q_mean", "pct_below_min", "pct_above_max", "pct_right", "pct_obtuse"]
    if with_domain:
        exact += ["n_free_triangles", "n_below_min_free"]
        close_abs += ["free_min_angle"]
if with_domain:
    exact += ["n_steiner", "n_forced_corners"]
bad = []
for k in exact:
    if a.get(k) != m.get(k):
        bad.append("%s: acute %s, meshcheck %s" % (k, json.dumps(a.get(k)), json.dumps(m.get(k))))
def differ(x, y, tol):
    if x is None or y is None:
        return x is not y
    return abs(x - y) > tol
for k in close_abs:
    if differ(a.get(k), m.get(k), 1e-9):
        bad.append("%s: acute %r, meshcheck %r" % (k, a.get(k), m.get(k)))
for k in close_rel:
    if differ(a.get(k), m.get(k), 1e-9 * max(1.0, abs(m.get(k) or 0.0))):
        bad.append("%s: acute %r, meshcheck %r" % (k, a.get(k), m.get(k)))
if with_domain:
    # The first five corners by angle (ties may come in another order).
    fa = sorted((round(c["angle"], 9), tuple(c["point"])) for c in a["forced_corners"])
    fm = sorted((round(c["angle"], 9), tuple(c["point"])) for c in m["forced_corners"])
    if fa != fm:
        bad.append("forced_corners: acute %s, meshcheck %s" % (fa, fm))
if bad:
    print("FAIL %s: %s" % (label, "; ".join(bad)))
    sys.exit(1)
if mode == "domain":
    print("ok   %s: %d forced corners%s" % (label, m["n_forced_corners"], "".join(
        ", %.6g" % c["angle"] for c in m["forced_corners"])))
else:
    print("ok   %s: %d triangles, angles %.6f..%.6f, %d right, %d obtuse%s" % (
        label, m["n_triangles"], m["min_angle"] or 0, m["max_angle"] or 0, m["n_right"], m["n_obtuse"],
        ", %s Steiner, %d forced corners" % (m["n_steiner"], m["n_forced_corners"]) if with_domain else ""))
EOF

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
status=0
n=0

# compare MODE LABEL MESH [DOMAIN]
compare() {
  local mode="$1" label="$2" mesh="$3" dom="${4:-}" rc
  local extra=()
  [ -n "$dom" ] && extra=(--domain "$dom")
  # acute exit 1 and meshcheck exit 1/2 are verdicts (bounds, conformity), not failures to run.
  rc=0; "$acute" stats "$mesh" --json --histogram "${extra[@]}" > "$tmp/a.json" 2> "$tmp/a.err" || rc=$?
  if [ "$rc" -gt 1 ]; then echo "FAIL $label: acute stats exit $rc: $(head -c 300 "$tmp/a.err")"; status=1; return 0; fi
  rc=0; python3 "$meshcheck" "$mesh" --json --histogram "${extra[@]}" > "$tmp/m.json" 2> "$tmp/m.err" || rc=$?
  if [ "$rc" -gt 2 ]; then echo "FAIL $label: meshcheck exit $rc: $(head -c 300 "$tmp/m.err")"; status=1; return 0; fi
  n=$((n + 1))
  python3 -c "$compare_py" "$tmp/a.json" "$tmp/m.json" "$label" "$mode" "$([ -n "$dom" ] && echo 1 || echo 0)" || status=1
}

shopt -s nullglob
first_mesh=""
for mesh in "$mesh_dir"/*.off "$mesh_dir"/*.obj "$mesh_dir"/*.ele; do
  [ -z "$first_mesh" ] && first_mesh="$mesh"
  name="$(basename "$mesh")"
  stem="${name%%.*}"
  compare mesh "$name" "$mesh"
  if [ -f "$domains/$stem.poly" ]; then compare mesh "$name with $stem.poly" "$mesh" "$domains/$stem.poly"; fi
done
if [ -n "$first_mesh" ] && [ -d "$domains" ]; then
  for dom in "$domains"/*.poly ${cgshop:+"$cgshop"/*.json}; do
    compare domain "domain $(basename "$dom")" "$first_mesh" "$dom"
  done
fi
if [ "$n" -eq 0 ]; then echo "compare_stats_meshcheck: no mesh compared in $mesh_dir" >&2; exit 2; fi
if [ "$status" -eq 0 ]; then echo "all $n comparisons agree"; else echo "MISMATCHES found"; fi
exit "$status"
