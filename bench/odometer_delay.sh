#!/usr/bin/env bash
# The odometer's delay as a calibration state (calibration.estimate_odometer_delay): the field
# preset simulated with its wheel stamps late by a delay (default 50 ms), calibrated by both
# estimators with the state on and off, and the same drive on time with the state on. Prints per
# seed and estimator the estimated delay and its sigma, and the calibration's NEES (7 observable
# states) and yaw and p_b_m.y errors with and without the state, against the on-time drive; then
# per estimator the delay's mean error, its spread, the mean claimed sigma and how many runs are
# within 5 ms.
# Usage: bench/odometer_delay.sh [delay_s] [seed...]   (default 0.05 and 211 212 213; about a
# minute per seed)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="${GIOCAL_BIN:-$root/build/apps/giocal}"
delay="${1:-0.05}"
shift || true
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(211 212 213)
work="$(mktemp -d /tmp/giocal_delay.XXXXXX)"
trap 'rm -rf "$work"' EXIT
# The preset with the delay; its navigation file by absolute path.
sed -e "s#\.\./\.\./data/#$root/data/#" \
  -e "s/^  slip_duration_s: \(.*\)/  slip_duration_s: \1\n  delay_s: $delay/" \
  "$root/config/sim/field.yaml" > "$work/late.yaml"
sed -e "s#\.\./\.\./data/#$root/data/#" "$root/config/sim/field.yaml" > "$work/on_time.yaml"
sed -e "s/estimate_odometer_delay: 0/estimate_odometer_delay: 1/" "$root/config/giocal.yaml" \
  > "$work/with_delay.yaml"
printf "%-5s %-4s %-8s %10s %8s %8s %10s %10s\n" seed est drive "t_d ms" "sd ms" "NEES7" \
  "yaw err" "p_y err"
for seed in "${seeds[@]}"; do
  "$giocal" simulate --config "$work/late.yaml" --seed "$seed" --out "$work/late$seed" > /dev/null
  "$giocal" simulate --config "$work/on_time.yaml" --seed "$seed" --out "$work/on$seed" \
    > /dev/null
  for est in ekf fgo; do
    for run in "late with_delay" "late default" "on with_delay"; do
      set -- $run
      out="$work/out_$1_$2_$est$seed"
      config="$root/config/giocal.yaml"
      [ "$2" = with_delay ] && config="$work/with_delay.yaml"
      "$giocal" calibrate --data "$work/$1$seed" --estimator "$est" --config "$config" \
        --out "$out" --quiet > /dev/null
      /usr/bin/python3 - "$out/summary.json" "$seed" "$est" "$1/$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
t_d = j["final"].get("t_d_odo")
sd = j["sd"].get("t_d_odo")
e = j["error"]
cell = lambda x, f: (f % x) if x is not None else "-"
row = "%-5s %-4s %-8s %10s %8s %8.2f %10.3f %10.4f" % (
    sys.argv[2], sys.argv[3], sys.argv[4].replace("with_delay", "t_d").replace("default", "off"),
    cell(t_d and 1e3 * t_d, "%.1f"), cell(sd and 1e3 * sd, "%.1f"), e["nees7"],
    e["rpy_b_m_deg"][2], e["p_b_m"][1])
print(row)
PY
    done
  done
done | tee "$work/rows.txt"
echo "truth: t_d = $delay s on the late drives, 0 on time; yaw error in degrees, p_y in metres"
/usr/bin/python3 - "$work/rows.txt" "$delay" <<'PY'
import sys, statistics as st
truth = {"late/t_d": 1e3 * float(sys.argv[2]), "on/t_d": 0.0}
rows = [l.split() for l in open(sys.argv[1])]
for drive, t in truth.items():
    for est in ("ekf", "fgo"):
        e = [float(r[3]) - t for r in rows if r[1] == est and r[2] == drive]
        sd = [float(r[4]) for r in rows if r[1] == est and r[2] == drive]
        if not e:
            continue
        spread = st.stdev(e) if len(e) > 1 else float("nan")
        print("%-8s %-4s seeds %2d: mean error %5.1f ms, spread %4.1f ms, mean sigma %4.1f ms, "
              "within 5 ms %d of %d" % (drive, est, len(e), st.mean(e), spread, st.mean(sd),
                                        sum(abs(x) < 5 for x in e), len(e)))
PY
