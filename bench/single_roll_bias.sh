#!/usr/bin/env bash
# The field preset's extrinsic roll with one receiver, on drives with (almost) no noise: every
# rover-alone effect off (orbit and satellite clock errors, drifts, receiver clock, half cycles,
# ionosphere and wet troposphere spread), no GNSS noise, IMU and odometer noise near zero, no IMU
# scale or misalignment, open sky throughout. What is left of an estimator's error there is not
# noise. Per seed, the EKF's roll error and sigma: with a base (RTK), alone (--gnss single), and
# alone under a sky of GPS, Galileo and BeiDou above 10 degrees (the preset: GPS above 24).
# Usage: bench/single_roll_bias.sh [seed...]   (default 6201 6203 6204; about 40 s per seed)
#        ESTIMATOR=fgo for the factor graph; CONFIG=<yaml> adds a calibrate --config to the
#        single runs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="${GIOCAL_BIN:-$root/build/apps/giocal}"
est="${ESTIMATOR:-ekf}"
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
seeds=("${@:-6201 6203 6204}")
read -r -a seeds <<< "${seeds[*]}"
work="$(mktemp -d /tmp/giocal_roll_bias.XXXXXX)"
trap 'rm -rf "$work"' EXIT
python3 - "$root/config/sim/field.yaml" "$work" "$root" <<'PY'
import re, sys
src, work, root = sys.argv[1:]
s = open(src).read().replace("../../data/", root + "/data/")
def put(s, key, value):
    pattern = re.compile(r"^(  " + re.escape(key) + r": )[^\n#]*", re.M)
    if not pattern.search(s):
        sys.exit("field.yaml changed: no '" + key + "' to set; update this script")
    return pattern.sub(lambda m: m.group(1) + value + " ", s, count=1)
for key, value in [("arw_deg_sqrt_h", "0.01"), ("vrw_m_s_sqrt_h", "0.001"),
                   ("gyro_bias_rw_deg_h_sqrt_h", "0.0"), ("accel_bias_rw_mgal_sqrt_s", "0.0"),
                   ("scale_ppm", "0"), ("misalignment_deg", "0"), ("speed_sigma", "0.002"),
                   ("yaw_rate_sigma_deg_s", "0.05"), ("speed_quantum", "0.0"),
                   ("code_sigma", "0.0"), ("phase_sigma", "0.0"), ("doppler_sigma", "0.0")]:
    s = put(s, key, value)
clean = "".join("  %s: 0\n" % k for k in [
    "orbit_error_m", "orbit_error_rate", "sat_clock_error_m", "sat_clock_random_walk",
    "vtec_random_walk", "zenith_wet_random_walk", "clock_step_s", "half_cycle_share",
    "clock_offset_sd", "clock_drift_sd", "zenith_wet_sd", "vtec_tecu", "vtec_gradient"])
start, end = s.index("  scenes:"), s.index("\ncalibration:") + 1
s = s[:start] + clean + "  scenes:\n    - {type: open_sky, start: 0, end: 100000}\n" + s[end:]
open(work + "/base.yaml", "w").write(s)
open(work + "/alone.yaml", "w").write(s.replace("  scenes:", "  base: none\n  scenes:", 1))
wide = put(put(s, "systems", "GEC"), "elevation_mask_deg", "10")
open(work + "/alone_wide.yaml", "w").write(wide.replace("  scenes:", "  base: none\n  scenes:", 1))
PY
config=()
[ -n "${CONFIG:-}" ] && config=(--config "$CONFIG")
printf "%-6s %-16s %-16s %-16s\n" seed "RTK roll err/sd" "single" "single GEC 10deg"
for seed in "${seeds[@]}"; do
  line="$seed"
  for v in base alone alone_wide; do
    "$giocal" simulate --config "$work/$v.yaml" --seed "$seed" --out "$work/$v-$seed" > /dev/null
    extra=()
    [ "$v" != base ] && extra=("${config[@]}")
    "$giocal" calibrate --data "$work/$v-$seed" --estimator "$est" --quiet "${extra[@]}" \
      --out "$work/run-$v-$seed" > /dev/null 2>&1 || true
    line+=" $(python3 -c "import json, sys
d = json.load(open(sys.argv[1]))
print('%+.4f/%.4f' % (d['error']['rpy_b_m_deg'][0], d['sd']['rpy_b_m_deg'][0]))" \
      "$work/run-$v-$seed/summary.json")"
  done
  read -r s a b c <<< "$line"
  printf "%-6s %-16s %-16s %-16s\n" "$s" "$a" "$b" "$c"
done
