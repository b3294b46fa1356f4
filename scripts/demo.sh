#!/usr/bin/env bash
# The main job on a bundled default domain: mesh meshes/A.poly and report on the result.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
./build/bin/acute mesh meshes/A.poly -o out/A.off
./build/bin/acute stats out/A.off --domain meshes/A.poly
./build/bin/acute render out/A.off -o out/A.svg
echo "wrote out/A.off and out/A.svg"
