#!/usr/bin/env bash
# Real GNSS on a moving antenna: the mosaic pair's static rover (data/real/mosaic-static-nagoya)
# moved along two laps of the field preset (`simulate --static-rover`, 261 s), the preset's IMU
# and odometer drawn per seed. For each seed: giocal rtk's fixes against the true antenna, then
# both calibrators with the base (fix rate, errors) and with the rover alone (--gnss single).
# PAIR=gsi instead moves the GSI pair's rover (two Trimble 5700, 3.3 km, GPS every 30 s) along
# the whole field drive (1244 s), with the base only (30 s is too long for TDCP pairs).
# The GNSS is the same real file for every seed; the seeds change the motion sensors' errors and
# the initial guess. Prints one row per seed and run, then the mean |error| per state and run,
# and the mean stated sigma of s_v and the roll (what the run holds, apart from its luck).
# Usage: [PAIR=mosaic|gsi] bench/moved_rover.sh [first seed, default 9101] [seeds, default 6]
#        CONFIG=<yaml> adds a calibrate --config to every run (e.g. a narrower sky: rtk.systems,
#        rtk.elevation_mask_deg and calibration.single.elevation_mask_deg).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
first="${1:-9101}"
count="${2:-6}"
giocal="${GIOCAL:-$root/build/apps/giocal}"
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d /tmp/giocal_moved_rover.XXXXXX)"
trap 'rm -rf "$work"' EXIT
# shellcheck source=bench/survey_ecef.sh
source "$root/bench/survey_ecef.sh"
if [ "${PAIR:-mosaic}" = gsi ]; then
  m="$root/data/real/gsi-static-0759-3040"
  rover="$m/07590920.05o" base="$m/30400920.05o" navs="$m/30400920.05n $m/07590920.05n"
  # The base as RTKLIB's test makefile states it (SOURCE.txt), the rover as the mean of RTKLIB's
  # fixed solution of the pair (rtklib_reference.pos).
  rover_pos="-3976219.1875,3382371.6044,3652511.1414" base_pos="-3978241.958,3382840.234,3649900.853"
  laps=10 schemes=base
else
  m="$root/data/real/mosaic-static-nagoya"
  rover="$m/rover.obs" base="$m/base.obs" navs="$m/base.nav"
  rover_pos="$(survey_ecef "$m/rover_position.txt")"
  base_pos="$(survey_ecef "$m/base_position.txt")"
  laps=2 schemes="base alone"
fi
sed -e "s/^  laps: 10/  laps: $laps/" -e "s|\.\./\.\./data/|$root/data/|" "$root/config/sim/field.yaml" \
  > "$work/field_laps.yaml"
rows="$work/rows.txt"
: > "$rows"
printf '%-6s %-12s %6s %9s %9s %8s %8s %8s %8s %8s %6s\n' seed run fix s_v s_w x_m y_m roll_deg \
  pitch_deg yaw_deg nees7
for seed in $(seq "$first" $((first + count - 1))); do
  for scheme in $schemes; do
    d="$work/$scheme$seed"
    extra=""
    [ "$scheme" = base ] && extra="--base $base --base-pos $base_pos"
    # shellcheck disable=SC2086
    "$giocal" simulate --config "$work/field_laps.yaml" --seed "$seed" --static-rover \
      "$rover" --rover-pos "$rover_pos" $extra --nav $navs --out "$d" > /dev/null
    if [ "$scheme" = base ]; then
      "$giocal" rtk --rover "$d/rover.obs" --base "$d/base.obs" --nav "$d/nav.rnx" \
        --base-pos "$base_pos" --out "$d/rtk.pos" | sed "s/^/  seed $seed: /"
    fi
    config=()
    [ -n "${CONFIG:-}" ] && config=(--config "$CONFIG")
    for e in ekf fgo; do
      "$giocal" calibrate --data "$d" --estimator "$e" --no-validate --quiet "${config[@]}" \
        --out "$d/$e" > /dev/null || true
      python3 - "$d/$e/summary.json" "$seed" "$scheme-$e" >> "$rows" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); e = s["error"]
print(sys.argv[2], sys.argv[3], s["status"].split(":")[0], s["fix_rate"], e["s_v"], e["s_w"],
      e["p_b_m"][0], e["p_b_m"][1], *e["rpy_b_m_deg"], e["nees7"], s["sd"]["s_v"],
      s["sd"]["rpy_b_m_deg"][0])
PY
      tail -1 "$rows" | awk '{printf "%-6s %-12s %6.3f %9.5f %9.5f %8.4f %8.4f %8.3f %8.3f %8.3f %6.1f%s\n",
        $1, $2, $4, $5, $6, $7, $8, $9, $10, $11, $12, ($3 == "ok" ? "" : "  " $3)}'
    done
  done
done
echo "mean |error| over seeds $first-$((first + count - 1)):"
awk '{n[$2]++; for (i = 5; i <= 11; i++) a[$2, i] += ($i < 0 ? -$i : $i); f[$2] += $4; q[$2] += $12
  sv[$2] += $13; sr[$2] += $14}
  END {for (r in n) printf "%-12s fix %.3f s_v %.5f s_w %.5f x %.4f y %.4f roll %.3f pitch %.3f yaw %.3f nees7 %.1f sigma s_v %.5f roll %.4f\n",
    r, f[r] / n[r], a[r, 5] / n[r], a[r, 6] / n[r], a[r, 7] / n[r], a[r, 8] / n[r], a[r, 9] / n[r],
    a[r, 10] / n[r], a[r, 11] / n[r], q[r] / n[r], sv[r] / n[r], sr[r] / n[r]}' "$rows" | sort
