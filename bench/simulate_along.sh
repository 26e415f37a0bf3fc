#!/usr/bin/env bash
# Real GNSS with synthesized motion sensors, measured where the truth is known: the field preset
# simulated (seed), giocal rtk's solution of its rover as the given trajectory, then
# `giocal simulate --trajectory` (the same preset's sensors along the fitted path, seed + 1000)
# with each knot spacing, and `calibrate` with both estimators. Prints the path's miss of the
# solution and each run's errors against the truth with its sigmas and NEES (7 observable
# states), beside the simulator's own dataset calibrated the same way.
# Usage: bench/simulate_along.sh [seed...]   (default 91; about 2 minutes per seed)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="$root/build/apps/giocal"
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(91)
work="$(mktemp -d /tmp/giocal_along.XXXXXX)"
trap 'rm -rf "$work"' EXIT
preset="$root/config/sim/field.yaml"
printf "%-5s %-14s %-4s %8s %8s %8s %8s %8s %8s %8s %8s %6s\n" seed dataset est "s_v err" sd \
  "pitch err" sd "yaw err" sd "|pxy| err" sd NEES
report() {  # seed label estimator summary.json
  /usr/bin/python3 - "$@" <<'PY'
import json, math, sys
seed, label, est, path = sys.argv[1:]
s = json.load(open(path)); e, sd = s["error"], s["sd"]
print("%-5s %-14s %-4s %8.5f %8.5f %8.2f %8.2f %8.2f %8.2f %8.3f %8.3f %6.1f" % (
    seed, label, est, e["s_v"], sd["s_v"], e["rpy_b_m_deg"][1], sd["rpy_b_m_deg"][1],
    e["rpy_b_m_deg"][2], sd["rpy_b_m_deg"][2], math.hypot(*e["p_b_m"][:2]),
    math.hypot(*sd["p_b_m"][:2]), e["nees7"]))
PY
}
for seed in "${seeds[@]}"; do
  sim="$work/sim$seed"
  "$giocal" simulate --config "$preset" --seed "$seed" --out "$sim" > /dev/null
  "$giocal" rtk --rover "$sim/rover.obs" --base "$sim/base.obs" --nav "$sim/nav.rnx" \
    --out "$sim/rtk.pos" > /dev/null
  for est in ekf fgo; do
    "$giocal" calibrate --data "$sim" --estimator $est --out "$work/c$seed$est" --quiet > /dev/null
    report "$seed" simulator $est "$work/c$seed$est/summary.json"
  done
  for knots in 0 0.5; do
    along="$work/along$seed-$knots"
    "$giocal" simulate --config "$preset" --seed $((seed + 1000)) --trajectory "$sim/rtk.pos" \
      --rover "$sim/rover.obs" --base "$sim/base.obs" --nav "$sim/nav.rnx" \
      --knot-spacing "$knots" --out "$along" | grep -o "knots every.*max [0-9.]* m" | sed "s/^/$seed   /"
    for est in ekf fgo; do
      "$giocal" calibrate --data "$along" --estimator $est --out "$work/a$seed$knots$est" \
        --quiet > /dev/null
      report "$seed" "along knots=$knots" $est "$work/a$seed$knots$est/summary.json"
    done
  done
done
