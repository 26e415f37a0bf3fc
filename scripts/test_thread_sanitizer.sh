#!/usr/bin/env bash
# The CalibratorQueue fed from one thread per sensor while another reads its getters, built with
# ThreadSanitizer (-O1 -g1, the EKF without the factor graph, only that test and what it links;
# into build-tsan/); fails on any data race or lock-order report. CI runs it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh" > /dev/null  # the packages (and the normal build)
cmake -S "$root" -B "$root/build-tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DGIOCAL_THREAD_SANITIZE=ON \
  -DGIOCAL_FACTOR_GRAPH=OFF -DGIOCAL_BENCH=OFF -DGIOCAL_EXAMPLES=OFF > /dev/null
cmake --build "$root/build-tsan" --target test_calibrator_queue -j "$(nproc)"
# halt_on_error: the first report ends the run with a non-zero status.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" \
  "$root/build-tsan/test/test_calibrator_queue"
echo "thread sanitizer: the CalibratorQueue test ran with no report"
