#!/usr/bin/env bash
# The time differences' slow part, real against simulated, under the field preset's sky (GPS
# above 24 degrees): every TDCP row at the true antenna (giocal_gnss_residuals --truth), its 1 s
# pairs averaged over 20, 60 and 120 s blocks without a break (bench/tdcp_slow_errors.py), RMS
# over rows [mm/s]. Real: the mosaic pair's static rover moved along two field laps (seed 21;
# the seed changes the motion sensors only). Simulated: field drives as a rover alone, with the
# simulator's defaults and with gnss.sat_clock_rate_sd 0 (the satellite clocks' rate left out).
# Usage: bench/tdcp_slow_errors.sh [seed...]   (default 6311-6316; about 10 s per seed)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="${GIOCAL:-$root/build/apps/giocal}"
residuals="$root/build/bench/giocal_gnss_residuals"
[ -x "$giocal" ] && [ -x "$residuals" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
seeds=("${@:-6311 6312 6313 6314 6315 6316}")
read -r -a seeds <<< "${seeds[*]}"
work="$(mktemp -d /tmp/giocal_tdcp_slow.XXXXXX)"
trap 'rm -rf "$work"' EXIT
# shellcheck source=bench/survey_ecef.sh
source "$root/bench/survey_ecef.sh"
sed -e "s|\.\./\.\./data/|$root/data/|" "$root/config/sim/field.yaml" > "$work/field.yaml"
sed -e "s/^  laps: 10/  laps: 2/" "$work/field.yaml" > "$work/laps2.yaml"
sed -e "s|^  systems: G|  systems: G\n  base: none\n  sat_clock_rate_sd: 0|" "$work/field.yaml" \
  > "$work/no_rate.yaml"
slow() {  # dataset folder, label: one line of the 20, 60 and 120 s figures
  local d="$1" pbg
  pbg=$(sed -n 's/^p_b_g: \[\(.*\)\]/\1/p' "$d/truth_calib.yaml" | tr -d ' ')
  "$residuals" --rover "$d/rover.obs" --nav "$d/nav.rnx" --truth "$d/truth.csv" --p-b-g "$pbg" \
    > "$d.rows.csv"
  printf '%-28s' "$2"
  for b in 20 60 120; do
    python3 "$root/bench/tdcp_slow_errors.py" "$d.rows.csv" --systems G --mask 24 --block "$b" \
      --min-rows $((b - 1)) | awk 'NR == 2 { printf " %8.3f", $3 }'
  done
  echo
}
printf '%-28s %8s %8s %8s   (mm/s, RMS over rows)\n' "GPS above 24 deg" 20s 60s 120s
m="$root/data/real/mosaic-static-nagoya"
"$giocal" simulate --config "$work/laps2.yaml" --seed 21 --static-rover "$m/rover.obs" \
  --rover-pos "$(survey_ecef "$m/rover_position.txt")" --nav "$m/base.nav" --out "$work/real" \
  > /dev/null
slow "$work/real" "real mosaic rover, moved"
for seed in "${seeds[@]}"; do
  "$giocal" simulate --config "$work/field.yaml" --seed "$seed" --no-base --out "$work/d$seed" \
    > /dev/null
  slow "$work/d$seed" "simulated $seed"
  "$giocal" simulate --config "$work/no_rate.yaml" --seed "$seed" --out "$work/n$seed" > /dev/null
  slow "$work/n$seed" "simulated $seed, no rate"
done
