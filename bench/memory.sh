#!/usr/bin/env bash
# Peak resident memory and speed of `giocal calibrate` on the field preset at its own length
# (10 laps, about 20 minutes) and extended to about 3 hours (87 laps), for both estimators: the
# online calibrator reads the files sample by sample, so memory must not grow with the drive.
# calibrate's validation at its end holds the drive in memory (docs/results.md): left out
# (--no-validate) unless VALIDATE=1.
# Usage: [VALIDATE=1] bench/memory.sh [seed] [laps_long] [estimators...]   (needs scripts/setup.sh's
#        build)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
giocal="$root/build/apps/giocal"
seed="${1:-3}"
laps_long="${2:-87}"
shift $(( $# > 2 ? 2 : $# ))
estimators=("${@:-ekf fgo}")
read -r -a estimators <<< "${estimators[*]}"
work="$(mktemp -d /tmp/giocal_memory.XXXXXX)"
trap 'rm -rf "$work"' EXIT
nav="$root/data/real/mosaic-static-nagoya/base.nav"

simulate() {  # laps -> dataset folder
  local laps="$1" cfg="$work/field_$1.yaml"
  sed -e "s/^  laps: .*/  laps: $laps/" -e "s|nav_file: .*|nav_file: $nav|" \
    "$root/config/sim/field.yaml" > "$cfg"
  "$giocal" simulate --config "$cfg" --out "$work/data_$laps" --seed "$seed" > /dev/null
  rm -f "$work/data_$laps/truth.csv"  # not read by calibrate; the largest file
  echo "$work/data_$laps"
}

validation=(--no-validate)
[ "${VALIDATE:-}" = 1 ] && validation=()
printf "%-4s %6s %10s %10s %10s %12s\n" est laps "data s" "wall s" "x real" "peak RSS MB"
for laps in 10 "$laps_long"; do
  data="$(simulate "$laps")"
  for est in "${estimators[@]}"; do
    out="$work/out_${est}_$laps"
    /usr/bin/time -f "%M" -o "$work/rss" "$giocal" calibrate --data "$data" --estimator "$est" \
      --out "$out" "${validation[@]}" > /dev/null
    python3 - "$out/summary.json" "$work/rss" "$est" "$laps" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
rss_mb = int(open(sys.argv[2]).read().split()[-1]) / 1024.0
print("%-4s %6s %10.0f %10.1f %10.0f %12.1f" % (sys.argv[3], sys.argv[4], s["data_duration_s"],
      s["wall_time_s"] + s["load_time_s"], s["data_duration_s"] / (s["wall_time_s"] + s["load_time_s"]), rss_mb))
PY
  done
  rm -rf "$data"
done
