#!/usr/bin/env bash
# Per-GNSS-epoch latency and speed of both estimators on the paper and field presets, each run
# alone on one core (taskset), from calibrate's summary.json (timing_s): mean, 50th and 99th
# percentile, maximum, and the run's real-time factor. Usage: bench/latency.sh [seed...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="$root/build/apps/giocal"
seeds=("${@:-21 22}")
read -r -a seeds <<< "${seeds[*]}"
work="$(mktemp -d /tmp/giocal_latency.XXXXXX)"
trap 'rm -rf "$work"' EXIT
printf "%-6s %-4s %5s %9s %9s %9s %9s %9s\n" preset est seed "mean ms" "p50 ms" "p99 ms" "max ms" "x real"
for preset in paper field; do
  for seed in "${seeds[@]}"; do
    data="$work/${preset}_$seed"
    "$giocal" simulate --config "$root/config/sim/$preset.yaml" --out "$data" --seed "$seed" > /dev/null
    for est in ekf fgo; do
      taskset -c 0 "$giocal" calibrate --data "$data" --estimator "$est" --out "$work/out" \
        --overwrite > /dev/null
      python3 - "$work/out/summary.json" "$preset" "$est" "$seed" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timing_s"]
print("%-6s %-4s %5s %9.2f %9.2f %9.2f %9.2f %9.0f" % (sys.argv[2], sys.argv[3], sys.argv[4],
      1e3 * t["gnss_epoch_mean_s"], 1e3 * t["gnss_epoch_p50_s"], 1e3 * t["gnss_epoch_p99_s"],
      1e3 * t["gnss_epoch_max_s"], s["real_time_factor"]))
PY
    done
  done
done
