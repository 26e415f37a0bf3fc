#!/usr/bin/env bash
# The README's main job: install, build, simulate the reference paper's dataset, check it, run RTK
# on its GNSS data, calibrate it with both estimators and print them side by side, then
# dead-reckon through 100 s without GNSS with the initial guess and with the calibration.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
giocal="$root/build/apps/giocal"
demo="$root/build/demo"   # the demo's own scratch folder inside build/
rm -rf "$demo"
mkdir -p "$demo"

echo
echo "== giocal simulate: the reference paper's simulation (IMU, odometer, rover/base GNSS, truth)"
"$giocal" simulate --config "$root/config/sim/paper.yaml" --out "$demo/paper" --seed 1
echo
echo "== giocal check: what the dataset holds"
"$giocal" check --data "$demo/paper"
echo
echo "== giocal rtk on the simulated rover and base"
base=$(sed -n 's/.*base_position_ecef: \[\(.*\)\].*/\1/p' "$demo/paper/dataset.yaml" | tr -d ' ')
"$giocal" rtk --rover "$demo/paper/rover.obs" --base "$demo/paper/base.obs" \
  --nav "$demo/paper/nav.rnx" --base-pos "$base" --out "$demo/paper_rtk.pos"
echo
echo "== true calibration of the simulated robot (what calibrate must find)"
grep -v '^#' "$demo/paper/truth_calib.yaml"
echo
echo "== giocal calibrate --estimator ekf (initial guess in dataset.yaml, errors against the truth)"
"$giocal" calibrate --data "$demo/paper" --estimator ekf --out "$demo/calib_ekf"
echo
echo "== giocal compare: the EKF and the sliding-window factor graph on the same data"
"$giocal" compare --data "$demo/paper" --out "$demo/compare"
echo
echo "== giocal deadreckon: what the calibration is worth (100 s without GNSS from +40 s)"
"$giocal" deadreckon --data "$demo/paper" --calibration guess --start 40 --duration 100 \
  --out "$demo/dr_guess"
"$giocal" deadreckon --data "$demo/paper" --calibration "$demo/calib_ekf/summary.json" \
  --start 40 --duration 100 --out "$demo/dr_ekf"
