#!/usr/bin/env bash
# Issue 5's bench: time to an acute mesh at ~10k, ~100k and ~1M triangles (5k, 50k, 500k vertices)
# on the unit square, meshes/A.poly and meshes/superior.poly, beside CGAL Mesh_2 (largest min-angle
# bound that terminates, 30° so far) and the same + Lloyd (10 iterations) at the same vertex count,
# in the same run. Each output judged by meshcheck (--tolerance 1e-10): time, cpu, peak memory
# (/usr/bin/time), % obtuse, max angle. A thin preset of bench/compare/run_compare.py.
#
#   bench/acute_bench.sh --quick          # ~10k triangles only
#   bench/acute_bench.sh                  # ~10k, ~100k, ~1M triangles (1M: minutes per mesher; Lloyd at 1M may hit the timeout)
#   bench/acute_bench.sh --quick --domains square      # any run_compare.py option overrides the preset
#
# Needs a Release build with the CGAL driver (apt-get install libcgal-dev time; then
#   cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2 --target acute_cli cgal_mesh2);
# BUILD=dir picks another build folder, MESHCHECK=path the referee. Results: results/bench/<date>/acute_bench_{quick,full}.md and .json
# (not committed).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
mode=full
if [[ "${1:-}" == "--quick" ]]; then
  mode=quick
  shift
fi
if [[ $mode == quick ]]; then
  preset=(--quick --sizes 5000 --timeout 300)
else
  preset=(--sizes 5000,50000,500000 --reps 1 --timeout 900)
fi
# The referee: ../shared/tools/meshcheck beside the repository, else /work/shared (worktrees), or MESHCHECK=path.
meshcheck=${MESHCHECK:-../shared/tools/meshcheck}
[[ -f $meshcheck ]] || meshcheck=/work/shared/tools/meshcheck
[[ -x /usr/bin/time ]] || echo "acute_bench: /usr/bin/time missing (apt-get install time): no cpu time or peak memory" >&2
exec python3 bench/compare/run_compare.py "${preset[@]}" --name "acute_bench_$mode" --no-million \
  --domains square,A,superior --meshers acute,cgal-max,cgal-max+lloyd --meshcheck "$meshcheck" --meshcheck-tolerance 1e-10 \
  --acute "$build/bin/acute" --cgal "$build/bin/cgal_mesh2" --out "results/bench/$(date -u +%F)" "$@"
