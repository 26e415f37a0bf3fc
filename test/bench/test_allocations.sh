#!/bin/bash
# The heap allocations the calibrator makes per sample (bench/allocations.cc, paper preset seed 1,
# steady state): both estimators allocate nothing per odometer sample; per IMU sample the EKF
# allocates nothing either (since the queue of released rover epochs is a RingQueue, not a
# std::deque that took a block every ten epochs), the factor graph at most one (inside
# Calibrator::release, once in 9901 samples; mean 0.0). Before the EKF kept its clones in
# place and its linearization storage per kind of model: 0.2 per IMU sample, 22 at the most.
# usage: test_allocations.sh <giocal_allocations>
set -euo pipefail
out=$("$1")
echo "$out"
check() {  # estimator, what ("IMU" or "odometer"), largest mean, largest worst
  echo "$out" | awk -v est="$1" -v what="$2" -v mean="$3" -v worst="$4" '
    $1 == est && $2 == what && $3 == "sample" {
      found = 1
      if ($5 > mean || $6 > worst) {
        printf "FAIL: %s %s sample: mean %s (at most %s), worst %s (at most %s)\n", est, what,
          $5, mean, $6, worst
        bad = 1
      }
    }
    END { if (!found) { print "FAIL: no line for " est " " what; exit 1 } exit bad }'
}
check ekf odometer 0 0
check ekf IMU 0 0
check fgo odometer 0 0
check fgo IMU 0.01 1
echo "allocations per sample within bounds"
