#!/usr/bin/env bash
# The robot's build for 64-bit ARM: the EKF calibrator without the factor graph (and without ROS 1
# bags, whose Debian library has no arm64 package), cross-built with Debian's toolchain into
# build-aarch64/, its fast tests run under qemu-user, then a simulated paper-preset drive
# calibrated there and compared with the x86 build's calibration. Needs the full build
# (scripts/setup.sh). CI runs it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh" > /dev/null  # the packages and the x86 build
bash "$root/scripts/install_missing.sh" crossbuild-essential-arm64 qemu-user bc \
  libyaml-cpp0.7:arm64 libboost-program-options-dev:arm64 libboost-filesystem-dev:arm64 \
  libsqlite3-dev:arm64 libgtest-dev:arm64
arm="$root/build-aarch64"
# libyaml-cpp-dev is not multi-arch: its arm64 package would remove the x86 one. Its files are
# unpacked beside the build instead (the library itself, libyaml-cpp0.7:arm64, is installed).
yaml="$arm/deps/yaml-cpp"
if [ ! -d "$yaml/usr/lib/aarch64-linux-gnu/cmake/yaml-cpp" ]; then
  mkdir -p "$arm/deps" && rm -rf "$yaml"
  (cd "$arm/deps" && apt-get download -qq libyaml-cpp-dev:arm64 libyaml-cpp0.7:arm64)
  for deb in "$arm"/deps/libyaml-cpp*_arm64.deb; do dpkg-deb -x "$deb" "$yaml"; done
fi
cmake -S "$root" -B "$arm" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/aarch64-linux-gnu.cmake" \
  -DCMAKE_BUILD_TYPE=Release -DGIOCAL_FACTOR_GRAPH=OFF -DGIOCAL_ROS1_BAGS=OFF \
  -DGIOCAL_BENCH=OFF -DGIOCAL_EXAMPLES=OFF \
  -Dyaml-cpp_DIR="$yaml/usr/lib/aarch64-linux-gnu/cmake/yaml-cpp" > /dev/null
cmake --build "$arm" -j "$(nproc)"
file "$arm/apps/giocal" | grep -q "ARM aarch64" || { echo "aarch64: giocal is not an ARM binary" >&2; exit 1; }
# The tests run through CMAKE_CROSSCOMPILING_EMULATOR (qemu-aarch64). Not the threaded queue's:
# it simulates and replays a whole drive before its threads start, minutes under emulation; it
# runs natively and under ThreadSanitizer (scripts/test_thread_sanitizer.sh).
(cd "$arm" && ctest --output-on-failure -j "$(nproc)" -L fast -E CalibratorQueue)

# A simulated paper-preset drive (the x86 simulator) calibrated by both builds' EKF.
work="$(mktemp -d /tmp/giocal_arm.XXXXXX)"
trap 'rm -rf "$work"' EXIT
"$root/build/apps/giocal" simulate --config "$root/config/sim/paper.yaml" --out "$work/data" \
  --seed 1 > /dev/null
"$root/build/apps/giocal" calibrate --data "$work/data" --estimator ekf --quiet --out "$work/x86" \
  > /dev/null
start=$(date +%s.%N)
qemu-aarch64 -L /usr/aarch64-linux-gnu "$arm/apps/giocal" calibrate --data "$work/data" \
  --estimator ekf --quiet --out "$work/arm" > /dev/null
echo "aarch64: calibrate under qemu took $(echo "$(date +%s.%N) - $start" | bc) s"
python3 "$root/scripts/compare_calibrations.py" "$work/x86/calibration.csv" \
  "$work/arm/calibration.csv"
