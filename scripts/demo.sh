#!/usr/bin/env bash
# The README's main job: install, build, then
#  1. a well-observed drive: five laps of the field preset (400 Hz IMU, turns both ways), checked,
#     calibrated by the EKF and compared with the factor graph: every parameter converges;
#  2. a weakly observed one: the reference paper's drive, where the mounting yaw is barely seen,
#     what the observability advisor says of it before calibrating, and what the run says after;
#  3. what the calibration is worth: 100 s dead-reckoned without GNSS, the guess against it, and
#     the same checked without a truth (validate);
#  4. the report page of the field calibration, whose path it prints last.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
giocal="$root/build/apps/giocal"
demo="$root/build/demo"   # the demo's own scratch folder inside build/
rm -rf "$demo"
mkdir -p "$demo"

echo
echo "== 1. A well-observed drive: the field preset, 5 of its 10 laps (about 10 minutes of data)"
# The preset with fewer laps; its nav file path made absolute, since the copy lives elsewhere.
sed -e 's/^\(  laps:\) 10/\1 5/' -e "s|\.\./\.\./data/|$root/data/|" \
  "$root/config/sim/field.yaml" > "$demo/field_5_laps.yaml"
"$giocal" simulate --config "$demo/field_5_laps.yaml" --out "$demo/field" --seed 7
echo
echo "-- giocal check: what the dataset holds"
"$giocal" check --data "$demo/field"
echo
echo "-- true calibration of the simulated robot (what calibrate must find)"
grep -v '^#' "$demo/field/truth_calib.yaml"
echo
echo "-- giocal calibrate --estimator ekf: converges live, then the estimate, its sigma, its error"
"$giocal" calibrate --data "$demo/field" --estimator ekf --out "$demo/field_ekf"
echo
echo "-- giocal compare: the EKF and the sliding-window factor graph on the same data"
"$giocal" compare --data "$demo/field" --out "$demo/field_compare"

echo
echo "== 2. A weakly observed drive: the reference paper's (150 s, one circle-like loop)"
"$giocal" simulate --config "$root/config/sim/paper.yaml" --out "$demo/paper" --seed 1
echo
echo "-- giocal observability: what this drive can calibrate, before calibrating"
"$giocal" observability --data "$demo/paper" --out "$demo/paper_observability"
echo
echo "-- giocal calibrate: the yaw of q_b_m stays near its prior, and the run says so"
"$giocal" calibrate --data "$demo/paper" --estimator ekf --out "$demo/paper_ekf"

echo
echo "== 3. What the calibration is worth: 100 s without GNSS on the field drive (from +200 s)"
"$giocal" deadreckon --data "$demo/field" --calibration guess --start 200 --duration 100 \
  --out "$demo/dr_guess"
"$giocal" deadreckon --data "$demo/field" --calibration "$demo/field_ekf/summary.json" \
  --start 200 --duration 100 --out "$demo/dr_ekf"
echo
echo "-- giocal validate: the same question without a truth, on five outages against the RTK fixes"
"$giocal" validate --data "$demo/field" --run "$demo/field_ekf" --quiet --out "$demo/validate"

echo
echo "== 4. The report page of the field calibration"
"$giocal" report --run "$demo/field_ekf" --data "$demo/field" --out "$demo/report"
echo
echo "demo done; the report: $demo/report/index.html"
