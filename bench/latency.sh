#!/usr/bin/env bash
# Per-GNSS-epoch latency and speed of both estimators on the paper and field presets, each run
# alone on one core (taskset), from calibrate's summary.json (timing_s): mean, 50th and 99th
# percentile, maximum, and the run's real-time factor. The factor graph runs twice: with its own
# Gauss-Newton (the default, "fgo") and with Ceres ("fgo-ceres", fgo.solver: ceres); the last
# lines give the ratio of their mean latencies measured in this run. With RUNS=N in the
# environment each calibration runs N times and the run of the smallest wall time is reported
# (the first run after a simulation is colder; this VM's speed drifts by a few percent).
# Usage: [RUNS=N] bench/latency.sh [seed...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="$root/build/apps/giocal"
seeds=("${@:-21 22}")
read -r -a seeds <<< "${seeds[*]}"
work="$(mktemp -d /tmp/giocal_latency.XXXXXX)"
trap 'rm -rf "$work"' EXIT
printf "fgo:\n  solver: ceres\n" > "$work/ceres.yaml"
printf "%-6s %-9s %5s %9s %9s %9s %9s %9s\n" preset est seed "mean ms" "p50 ms" "p99 ms" "max ms" "x real" \
  | tee "$work/table.txt"
for preset in paper field; do
  for seed in "${seeds[@]}"; do
    data="$work/${preset}_$seed"
    "$giocal" simulate --config "$root/config/sim/$preset.yaml" --out "$data" --seed "$seed" > /dev/null
    for est in ekf fgo fgo-ceres; do
      extra=()
      [[ "$est" == fgo-ceres ]] && extra=(--config "$work/ceres.yaml")
      for run in $(seq "${RUNS:-1}"); do
        taskset -c 0 "$giocal" calibrate --data "$data" --estimator "${est%-ceres}" \
          --out "$work/out$run" --overwrite "${extra[@]}" > /dev/null
      done
      python3 - "$preset" "$est" "$seed" "$work"/out*/summary.json <<'PY' | tee -a "$work/table.txt"
import json, sys
preset, est, seed = sys.argv[1:4]
s = min((json.load(open(p)) for p in sys.argv[4:]), key=lambda r: r["wall_time_s"])
t = s["timing_s"]
print("%-6s %-9s %5s %9.2f %9.2f %9.2f %9.2f %9.0f" % (preset, est, seed,
      1e3 * t["gnss_epoch_mean_s"], 1e3 * t["gnss_epoch_p50_s"], 1e3 * t["gnss_epoch_p99_s"],
      1e3 * t["gnss_epoch_max_s"], s["real_time_factor"]))
PY
    done
  done
done
python3 - "$work/table.txt" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:]]
for preset in ("paper", "field"):
    mean = {est: [float(r[3]) for r in rows if r[0] == preset and r[1] == est] for est in ("fgo", "fgo-ceres")}
    if mean["fgo"] and mean["fgo-ceres"]:
        a, b = sum(mean["fgo"]) / len(mean["fgo"]), sum(mean["fgo-ceres"]) / len(mean["fgo-ceres"])
        print("%s: factor graph mean latency, Ceres / own Gauss-Newton = %.2f / %.2f ms = %.2fx" % (preset, b, a, b / a))
PY
