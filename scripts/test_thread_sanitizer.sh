#!/usr/bin/env bash
# The CalibratorQueue fed from one thread per sensor while another reads its getters, built with
# ThreadSanitizer (-O1 -g1, the EKF without the factor graph, only that test and what it links;
# into build-tsan/); fails on any data race or lock-order report. Then a negative control: the
# same test built from a copy of the sources whose health() getter reads the snapshot without its
# lock must be reported, or the check could not fail. CI runs it.
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

# The negative control, from a copy of the sources (data/ linked, not copied), built in the
# copy's build-tsan/ as the sources are in theirs: under CI's compiler cache (.ci/run: ccache with
# the clone as base directory) every object but the changed file's is then the build above's.
control="$root/build-tsan/control"
rm -rf "$control"
mkdir -p "$control/src"
tar -C "$root" --exclude=./build --exclude='./build-*' --exclude=./data --exclude=./.git -cf - . \
  | tar -C "$control/src" -xf -
ln -s "$root/data" "$control/src/data"
queue="$control/src/common/online/calibrator_queue.cc"
sed -i '/^CalibratorHealth CalibratorQueue::health() const {$/{n;d}' "$queue"
locks=$(grep -c 'lock_guard<std::mutex> lock(snapshot_mutex_)' "$queue")
[ "$locks" -eq 3 ] || { echo "negative control: expected 3 snapshot locks left, found $locks"; exit 1; }
cmake -S "$control/src" -B "$control/src/build-tsan" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DGIOCAL_THREAD_SANITIZE=ON \
  -DGIOCAL_FACTOR_GRAPH=OFF -DGIOCAL_BENCH=OFF -DGIOCAL_EXAMPLES=OFF > /dev/null
cmake --build "$control/src/build-tsan" --target test_calibrator_queue -j "$(nproc)" > /dev/null
if TSAN_OPTIONS="halt_on_error=1" "$control/src/build-tsan/test/test_calibrator_queue" \
  > "$control/report.txt" 2>&1; then
  echo "negative control: a getter without its lock ran with no report"
  exit 1
fi
grep -q "ThreadSanitizer: data race" "$control/report.txt" \
  || { echo "negative control: failed without a race report:"; tail -20 "$control/report.txt"; exit 1; }
grep -q "CalibratorQueue::health" "$control/report.txt" \
  || { echo "negative control: the race reported is not in health()"; exit 1; }
echo "thread sanitizer: the negative control (health() without its lock) was reported"
rm -rf "$control"
