#!/usr/bin/env bash
# The calibrator's budget on any machine: instructions per second of data, counted by valgrind's
# callgrind inside the online Calibrator's add*() and finish() calls only (what a robot runs:
# the estimation and its outputs; reading the files is left out), on datasets without truth.csv
# (a live check against a truth is evaluation, not robot work). Prints, per preset and estimator,
# the instructions, the data's duration, their ratio and the share of the five costliest
# functions; and the ratio again with glibc's vector memset/memcpy at every size (x86's rep
# string instructions, which glibc uses above 2 kB, are counted once per byte).
# Usage: bench/instructions.sh [ekf|fgo]   (default ekf; the paper preset seed 1 and the field
#        preset seed 77; about 2 minutes for the EKF)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
estimator="${1:-ekf}"
giocal="${GIOCAL:-$root/build/apps/giocal}"
command -v valgrind > /dev/null || { echo "valgrind missing: apt-get install valgrind"; exit 1; }
[ -x "$giocal" ] || { echo "build first: bash scripts/setup.sh"; exit 1; }
work="$(mktemp -d /tmp/giocal_instructions.XXXXXX)"
trap 'rm -rf "$work"' EXIT
for case in "paper 1" "field 77"; do
  read -r preset seed <<< "$case"
  d="$work/$preset"
  "$giocal" simulate --config "$root/config/sim/$preset.yaml" --out "$d" --seed "$seed" > /dev/null
  rm -f "$d/truth.csv" "$d/truth_calib.yaml"
  sed -i '/^  truth: /d' "$d/dataset.yaml"
  valgrind --tool=callgrind --callgrind-out-file="$work/$preset.cg" \
    --toggle-collect='giocal::Calibrator::add*' --toggle-collect='giocal::Calibrator::finish*' \
    "$giocal" calibrate --data "$d" --estimator "$estimator" --no-validate --out "$work/$preset.run" \
    --quiet > /dev/null 2> "$work/$preset.log"
  total=$(awk '/^summary:/ { print $2 }' "$work/$preset.cg")
  # The same run with glibc's vector memset/memcpy for every size: callgrind counts x86's
  # rep stosb/movsb (glibc's choice above 2 kB) once per byte, which no other machine pays.
  GLIBC_TUNABLES=glibc.cpu.x86_rep_stosb_threshold=0x40000000:glibc.cpu.x86_rep_movsb_threshold=0x40000000 \
    valgrind --tool=callgrind --callgrind-out-file="$work/$preset.vec.cg" \
    --toggle-collect='giocal::Calibrator::add*' --toggle-collect='giocal::Calibrator::finish*' \
    "$giocal" calibrate --data "$d" --estimator "$estimator" --no-validate --out "$work/$preset.run" \
    --overwrite --quiet > /dev/null 2>> "$work/$preset.log"
  vector_total=$(awk '/^summary:/ { print $2 }' "$work/$preset.vec.cg")
  duration=$(/usr/bin/python3 -c "import json, sys
print(json.load(open(sys.argv[1]))['data_duration_s'])" "$work/$preset.run/summary.json")
  /usr/bin/python3 -c "import sys
total, duration = float(sys.argv[1]), float(sys.argv[2])
print(f'{sys.argv[3]:5s} seed {sys.argv[4]:>3s} {sys.argv[5]}: {total / 1e6:8.1f} M instructions '
      f'for {duration:.0f} s of data = {total / duration / 1e6:.2f} M per second of data '
      f'({float(sys.argv[6]) / duration / 1e6:.2f} M with vector memset/memcpy)')" \
    "$total" "$duration" "$preset" "$seed" "$estimator" "$vector_total"
  callgrind_annotate --inclusive=no "$work/$preset.cg" 2> /dev/null \
    | awk '/file:function/ { go = 1; next } go && /^ *[0-9]/ && n < 5 { n++; print "    " $0 }' \
    | sed -E 's/\?\?\?://; s/\(\(\(Eigen.*$//' | cut -c1-150
done
