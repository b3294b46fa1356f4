#!/usr/bin/env bash
# The main job on a bundled default domain: mesh meshes/A.poly and report on the result.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/bin/acute mesh meshes/A.poly -o out/A.off --pictures out/A
./build/bin/acute stats out/A.off --domain meshes/A.poly
./build/bin/acute render out/A.off -o out/A.svg --domain meshes/A.poly
./build/bin/acute render out/A.off -o out/A_histogram.svg --histogram
echo "wrote out/A.off, out/A.svg (the mesh), out/A_histogram.svg (its angles) and out/A_before.svg /"
echo "out/A_after.svg (the CDT of the domain and the acute mesh, with their histograms)"
