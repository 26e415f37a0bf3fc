#!/usr/bin/env bash
# Installs, builds and runs every test (the README's test command).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
GIOCAL_EXTRA_PACKAGES="chromium" bash "$root/scripts/setup.sh"
cd "$root/build"
ctest --output-on-failure -j "$(nproc)"
