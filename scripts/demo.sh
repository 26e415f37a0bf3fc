#!/usr/bin/env bash
# The README's main job: install, build, and run giocal on the data shipped in data/.
# Until the estimators exist (issues 3-6) it runs what exists and says what does not.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
giocal="$root/build/apps/giocal"
echo
"$giocal" --help
echo
for cmd in simulate rtk calibrate compare; do
  "$giocal" "$cmd" || true
done
