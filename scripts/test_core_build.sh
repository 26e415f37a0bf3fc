#!/usr/bin/env bash
# The robot's build: the EKF calibrator without the factor graph (-DGIOCAL_FACTOR_GRAPH=OFF, into
# build-core/): builds it and its tests, runs them, checks that the giocal it makes links neither
# Ceres, SuiteSparse nor glog, and that its EKF calibration of a simulated paper-preset drive is
# byte-identical to the full build's. Needs the full build (scripts/setup.sh). CI runs it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh" > /dev/null  # the packages and the full build
core="$root/build-core"
cmake -S "$root" -B "$core" -DCMAKE_BUILD_TYPE=Release -DGIOCAL_FACTOR_GRAPH=OFF \
  -DGIOCAL_BENCH=OFF > /dev/null
cmake --build "$core" -j "$(nproc)"
(cd "$core" && ctest --output-on-failure -j "$(nproc)")

# Its dynamic dependencies: none of the factor graph's.
deps="$(ldd "$core/apps/giocal")"
if grep -E -i 'ceres|cholmod|suitesparse|glog|gflags' <<< "$deps"; then
  echo "core build: giocal links a factor-graph library (above)" >&2
  exit 1
fi
echo "core build: giocal links none of ceres, cholmod/suitesparse, glog, gflags"

# The same calibration as the full build's, byte for byte.
work="$(mktemp -d /tmp/giocal_core.XXXXXX)"
trap 'rm -rf "$work"' EXIT
"$root/build/apps/giocal" simulate --config "$root/config/sim/paper.yaml" --out "$work/data" \
  --seed 1 > /dev/null
"$root/build/apps/giocal" calibrate --data "$work/data" --estimator ekf --quiet --out "$work/full" \
  > /dev/null
"$core/apps/giocal" calibrate --data "$work/data" --estimator ekf --quiet --out "$work/core" \
  > /dev/null
cmp "$work/full/calibration.csv" "$work/core/calibration.csv"
echo "core build: calibration.csv byte-identical to the full build's"
# And it says what it lacks rather than failing obscurely.
if "$core/apps/giocal" calibrate --data "$work/data" --estimator fgo --quiet --out "$work/fgo" \
  > "$work/fgo.log" 2>&1; then
  echo "core build: --estimator fgo did not fail" >&2
  exit 1
fi
grep -q "built without the factor graph" "$work/fgo.log"
echo "core build: --estimator fgo names the missing factor graph"
