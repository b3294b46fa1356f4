#!/usr/bin/env bash
# Installs libacute into a temporary prefix, then builds and runs examples/ against the installed
# CMake package (find_package(acute CONFIG REQUIRED), acute::acute), as a user would.
#   scripts/test_install.sh [BUILD_DIR]
# BUILD_DIR: an existing build directory of this project to reuse (only the installed targets are
# built there; its cache is not changed). Without it a fresh Release build is configured in the
# temporary directory. JOBS (default 2) sets the build parallelism; KEEP=1 keeps the temporary
# directory. Exits non-zero on the first failure.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=${JOBS:-2}
work=$(mktemp -d "${TMPDIR:-/tmp}/acute-install.XXXXXX")
if [[ ${KEEP:-0} == 1 ]]; then echo "test_install: keeping $work"; else trap 'rm -rf "$work"' EXIT; fi
prefix=$work/prefix
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

step() { echo "== test_install: $*"; }
fail() { echo "test_install: FAILED: $*" >&2; exit 1; }

build=${1:-}
if [[ -z $build ]]; then
  build=$work/build
  step "configuring $root in $build"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DLIBACUTE_BUILD_TESTS=OFF -DLIBACUTE_BUILD_BENCH=OFF "${launcher[@]}" > "$work/configure.log" \
    || { cat "$work/configure.log"; fail "configure"; }
fi
[[ -f $build/CMakeCache.txt ]] || fail "$build is not a configured build directory"

# Build only what gets installed: the layer libraries and, when enabled, the CLI.
targets=()
for layer_file in "$root"/libacute/src/*/layer.cmake; do
  targets+=("acute_$(basename "$(dirname "$layer_file")")")
done
if grep -q '^LIBACUTE_BUILD_TOOLS:BOOL=ON' "$build/CMakeCache.txt"; then targets+=(acute_cli); fi
step "building ${targets[*]}"
cmake --build "$build" -j "$jobs" --target "${targets[@]}" > "$work/build.log" 2>&1 \
  || { tail -40 "$work/build.log"; fail "build"; }

step "installing into $prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "install"; }
for f in include/acute/mesher.h include/acute/mesh/mesh.h include/acute/io/io.h; do
  [[ -f $prefix/$f ]] || fail "$f not installed"
done
config=$(find "$prefix" -name acuteConfig.cmake -print -quit)
[[ -n $config ]] || fail "acuteConfig.cmake not installed"
[[ -f $(dirname "$config")/acuteConfigVersion.cmake ]] || fail "acuteConfigVersion.cmake not installed"
[[ -n $(find "$prefix" -name 'libacute_pipeline.a' -print -quit) ]] || fail "libacute_pipeline.a not installed"
if [[ " ${targets[*]} " == *" acute_cli "* ]]; then
  [[ -x $prefix/bin/acute ]] || fail "bin/acute not installed"
  "$prefix/bin/acute" --help > /dev/null || fail "installed acute --help"
fi

step "building examples/ against the installed package"
cmake -S "$root/examples" -B "$work/example" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  "${launcher[@]}" > "$work/example-configure.log" || { cat "$work/example-configure.log"; fail "example configure"; }
cmake --build "$work/example" -j "$jobs" > "$work/example-build.log" 2>&1 \
  || { tail -40 "$work/example-build.log"; fail "example build"; }

step "running the example"
out=$work/l_shape_acute.off
dual=$work/l_shape_dual.vtu
status=0
"$work/example/acute_example" "$out" "$dual" || status=$?
# 0: bounds met; 1: mesh written but bounds not met (reported, not a packaging failure).
[[ $status == 0 || $status == 1 ]] || fail "acute_example exited with $status"
[[ -s $out ]] || fail "$out missing or empty"
[[ -s $dual ]] || fail "$dual missing or empty"
read -r header < "$out"
[[ $header == OFF ]] || fail "$out does not start with OFF"
counts=$(grep -v '^#' "$out" | sed -n 2p)
n_vertices=${counts%% *}
(( n_vertices > 6 )) || fail "$out has only $n_vertices vertices"
[[ $status == 0 ]] || echo "test_install: note: the example mesh does not meet the angle bounds"
step "ok ($n_vertices vertices in $out)"
