// How long a robot's IMU callback is held by giocal: every addImu call timed, fed in time order
// from a simulated drive, with the Calibrator called directly (the estimation runs inside the
// call that releases the data) and through a CalibratorQueue with its worker thread (the call
// only enqueues). Prints p50, p99 and the worst call per estimator and front, measured in one run.
// Usage: giocal_add_latency [--preset config/sim/paper.yaml] [--seed N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/online/calibrator_queue.h"
#include "replay/estimator_factory.h"
#include "simulated_inputs.h"

using namespace giocal;

namespace {

struct Percentiles {
  double p50, p99, max;
};

Percentiles percentiles(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[static_cast<size_t>(q * double(v.size() - 1))]; };
  return {at(0.5), at(0.99), v.back()};
}

/// Feeds the drive in time order to `front` (Calibrator or CalibratorQueue); the IMU calls timed.
template <class Front>
std::vector<double> feed(const CalibrationInputs& in, Front& front) {
  std::vector<double> ms;
  ms.reserve(in.imu.size());
  size_t ko = 0, kr = 0, kb = 0;
  for (const ImuSample& s : in.imu) {
    while (ko < in.odom.size() && in.odom[ko].t <= s.t) front.addOdometer(in.odom[ko++]);
    while (kr < in.rover.epochs.size() && in.rover.epochs[kr].t <= s.t)
      front.addRover(in.rover.epochs[kr++]);
    while (kb < in.base.epochs.size() && in.base.epochs[kb].t <= s.t)
      front.addBase(in.base.epochs[kb++]);
    const auto t0 = std::chrono::steady_clock::now();
    front.addImu(s);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  const bench::PresetSeed ps = bench::presetAndSeed(argc, argv);
  const CalibrationInputs in = bench::simulatedInputs(ps, "giocal_add_latency");
  std::printf("%s seed %llu: %zu IMU samples\n", ps.preset.c_str(),
              static_cast<unsigned long long>(ps.seed), in.imu.size());
  std::printf("%-4s %-8s %10s %10s %10s\n", "est", "front", "p50 ms", "p99 ms", "max ms");
  for (const char* est : {"ekf", "fgo"}) {
    auto direct = makeCalibrator(est, in.description, in.base_e, CalibrationOptions{}, {}, nullptr);
    direct->addNavigation(in.nav);
    const Percentiles d = percentiles(feed(in, *direct));
    direct->finish();
    CalibratorQueue queue(
        makeCalibrator(est, in.description, in.base_e, CalibrationOptions{}, {}, nullptr));
    queue.addNavigation(in.nav);
    queue.start();
    const Percentiles q = percentiles(feed(in, queue));
    queue.finish();
    std::printf("%-4s %-8s %10.4f %10.4f %10.4f\n", est, "direct", d.p50, d.p99, d.max);
    std::printf("%-4s %-8s %10.4f %10.4f %10.4f\n", est, "queue", q.p50, q.p99, q.max);
    std::printf("%-4s worst call: queue / direct = %.3f\n", est, q.max / d.max);
  }
  return 0;
}
