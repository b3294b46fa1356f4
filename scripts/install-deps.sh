#!/usr/bin/env bash
# Installs the Debian packages libacute needs to build and test (run as root). Skips apt when all are present.
set -euo pipefail
packages=(build-essential cmake ccache python3
          libopenmesh-dev libeigen3-dev libgmp-dev libgtest-dev libbenchmark-dev liblbfgspp-dev libcli11-dev nlohmann-json3-dev)
# Peers used only by tests of our output formats (skipped when absent): meshio and gmsh.
[ "${ACUTE_MINIMAL_DEPS:-0}" = 1 ] || packages+=(python3-meshio gmsh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
