#!/usr/bin/env bash
# Installs the Debian packages giocal needs (only what is missing) and builds Release into build/.
# Sourced by demo.sh and test.sh; not one of the README's commands on its own.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
packages=(cmake g++ make libeigen3-dev libceres-dev libsuitesparse-dev libboost-program-options-dev libgtest-dev
  libyaml-cpp-dev nlohmann-json3-dev rtklib parallel librosbag-storage-dev libboost-filesystem-dev libsqlite3-dev python3-matplotlib)
# Packages only the tests need (scripts/test.sh: chromium, which renders the report's page).
read -r -a extra <<< "${GIOCAL_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
bash "$root/scripts/install_missing.sh" "${packages[@]}"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$(nproc)"
