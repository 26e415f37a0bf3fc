#!/usr/bin/env bash
# How the calibrators' accuracy and consistency depend on the GNSS epoch interval: simulated field
# drives (config/sim/field.yaml) with GNSS every 1, 5, 10 and 30 s (INTERVALS to change), both
# estimators with defaults. Prints one row per seed, interval and estimator (fix rate, errors,
# err/sigma of yaw and pitch, NEES7), then the mean per interval and estimator.
# Usage: [INTERVALS="1 30"] [ESTIMATORS=ekf] bench/gnss_interval.sh [first seed, default 9201]
#   [seeds, default 4]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
first="${1:-9201}"
count="${2:-4}"
intervals="${INTERVALS:-1 5 10 30}"
estimators="${ESTIMATORS:-ekf fgo}"
giocal="${GIOCAL:-$root/build/apps/giocal}"
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d /tmp/giocal_gnss_interval.XXXXXX)"
trap 'rm -rf "$work"' EXIT
rows="$work/rows.txt"
: > "$rows"
printf '%-6s %4s %-4s %6s %9s %8s %8s %8s %6s %8s %6s %6s\n' seed dt_s run fix s_v x_m y_m \
  pitch_deg p/sd yaw_deg y/sd nees7
for dt in $intervals; do
  rate="$(python3 -c "print(repr(1.0 / $dt))")"
  sed -e "s|\.\./\.\./data/|$root/data/|" \
    -e "/^gnss:/,/^[a-z]/s/^  rate_hz: .*/  rate_hz: $rate/" "$root/config/sim/field.yaml" \
    > "$work/field_$dt.yaml"
  for seed in $(seq "$first" $((first + count - 1))); do
    d="$work/$dt-$seed"
    "$giocal" simulate --config "$work/field_$dt.yaml" --seed "$seed" --out "$d" > /dev/null
    for e in $estimators; do
      "$giocal" calibrate --data "$d" --estimator "$e" --no-validate --quiet --out "$d/$e" \
        > /dev/null || true
      python3 - "$d/$e/summary.json" "$seed" "$dt" "$e" >> "$rows" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); e = s["error"]; sd = s["sd"]
print(sys.argv[2], sys.argv[3], sys.argv[4], s["fix_rate"], e["s_v"], e["p_b_m"][0], e["p_b_m"][1],
      e["rpy_b_m_deg"][1], abs(e["rpy_b_m_deg"][1]) / sd["rpy_b_m_deg"][1], e["rpy_b_m_deg"][2],
      abs(e["rpy_b_m_deg"][2]) / sd["rpy_b_m_deg"][2], e["nees7"], s["status"].split(":")[0])
PY
      tail -1 "$rows" | awk '{printf "%-6s %4s %-4s %6.3f %9.5f %8.4f %8.4f %8.3f %6.2f %8.3f %6.2f %6.1f %s\n",
        $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, ($13 == "ok" ? "" : $13)}'
    done
  done
done
echo "mean over seeds $first-$((first + count - 1)) (|error|, err/sigma, NEES7):"
awk '{k = sprintf("%4s %s", $2, $3); n[k]++; f[k] += $4; sv[k] += ($5 < 0 ? -$5 : $5)
  p[k] += ($8 < 0 ? -$8 : $8); ps[k] += $9; y[k] += ($10 < 0 ? -$10 : $10); ys[k] += $11; q[k] += $12}
  END {for (k in n) printf "dt %s  fix %.3f  s_v %.2e  pitch %.3f (err/sd %.2f)  yaw %.3f (err/sd %.2f)  nees7 %.1f\n",
    k, f[k] / n[k], sv[k] / n[k], p[k] / n[k], ps[k] / n[k], y[k] / n[k], ys[k] / n[k], q[k] / n[k]}' \
  "$rows" | sort -n -k2
