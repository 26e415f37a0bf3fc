#!/usr/bin/env bash
# The field preset with GNSS noise like the real pairs' (docs/results.md, GNSS): white noise at
# their level and multipath that changes slowly (gnss.multipath_*), against the preset as it is.
# Prints the simulated DD residuals' level, chi2 and epoch-to-epoch correlation the way the real
# pairs' were measured (the drive's open-sky first 320 s), then the EKF's or the factor graph's
# Monte Carlo on both.
# Usage: bench/real_like_gnss.sh [first seed] [seeds] [ekf|fgo]   (default 9501 6 ekf)
#        CODE=0.1 PHASE=0.0015 MP_CODE=0.12 MP_PHASE=0.001 TAU=20 override the noise [m, s];
#        PRESET_OUT=<file> only writes the preset there.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
first="${1:-9501}"
seeds="${2:-6}"
estimator="${3:-ekf}"
giocal="$root/build/apps/giocal"
mc="$root/build/bench/giocal_monte_carlo"
[ -x "$giocal" ] && [ -x "$mc" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d /tmp/giocal_real_like.XXXXXX)"
trap 'rm -rf "$work"' EXIT
preset="$work/field_real_like.yaml"
sed -e "s#^  nav_file: \.\./\.\./#  nav_file: $root/#" \
  -e "s#^  code_sigma: .*#  code_sigma: ${CODE:-0.1}\n  multipath_code_sigma: ${MP_CODE:-0.12}\n  multipath_tau_s: ${TAU:-20}#" \
  -e "s#^  phase_sigma: .*#  phase_sigma: ${PHASE:-0.0015}\n  multipath_phase_sigma: ${MP_PHASE:-0.001}#" \
  "$root/config/sim/field.yaml" > "$preset"
grep -q multipath_code_sigma "$preset" || { echo "field.yaml changed: update this script"; exit 1; }
if [ -n "${PRESET_OUT:-}" ]; then  # the preset alone, for other benches (PRESET= of rtk_under_trees.sh)
  cp "$preset" "$PRESET_OUT"
  echo "wrote $PRESET_OUT"
  exit 0
fi
for p in "$root/config/sim/field.yaml" "$preset"; do
  d="$work/sim"
  rm -rf "$d"
  "$giocal" simulate --config "$p" --out "$d" --seed "$first" > /dev/null
  base=$(sed -n 's/.*base_position_ecef: \[\(.*\)\].*/\1/p' "$d/dataset.yaml" | tr -d ' ')
  "$giocal" rtk --rover "$d/rover.obs" --base "$d/base.obs" --nav "$d/nav.rnx" --base-pos="$base" \
    --out "$work/rtk.pos" --overwrite > /dev/null
  "$root/build/bench/giocal_gnss_residuals" --rover "$d/rover.obs" --base "$d/base.obs" \
    --nav "$d/nav.rnx" --base-pos "$base" --pos "$work/rtk.pos" --frequencies 2 \
    > "$work/residuals.csv" 2> /dev/null
  /usr/bin/python3 "$root/bench/gnss_noise_fit.py" --first-s 320 \
    "$(basename "$p" .yaml)=$work/residuals.csv"
done
for p in "$root/config/sim/field.yaml" "$preset"; do
  "$mc" --preset "$p" --first "$first" --seeds "$seeds" --estimator "$estimator" --quiet 1 \
    | sed -n '/^Mean absolute/,/^guess/p'
done
