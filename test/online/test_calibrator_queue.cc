// The CalibratorQueue fed by one thread per sensor, as a robot's drivers call it: the calibration
// equals the single-threaded replay's, the getters are safe to call meanwhile, and the sensor
// callbacks only enqueue.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

#include "common/calibration/calibration_inputs.h"
#include "common/online/calibrator_queue.h"
#include "replay/estimator_factory.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

/// Threads that go through time slices together (C++17 has no std::barrier).
class Slices {
 public:
  explicit Slices(int threads) : threads_(threads) {}
  void arrive() {
    std::unique_lock<std::mutex> lock(m_);
    const long slice = slice_;
    if (++waiting_ == threads_) {
      waiting_ = 0;
      ++slice_;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return slice_ != slice; });
    }
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  int threads_, waiting_ = 0;
  long slice_ = 0;
};

TEST(CalibratorQueue, OneThreadPerSensorCalibratesAsTheOrderedReplay) {
  test::TempDir dir;
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  sim::writeDataset(sim::simulate(cfg, 17), dir.file("data"));
  const CalibrationInputs in = loadCalibrationInputs(dir.file("data"));
  const CalibrationRun ordered = replayInputs(in, {"ekf", {}, {}}, nullptr);

  CalibratorQueue queue(
      makeCalibrator("ekf", in.description, in.base_e, CalibrationOptions{}, {}, nullptr));
  queue.addNavigation(in.nav);
  queue.start();
  // Each thread feeds its sensor 0.1 s of data at a time, all threads slice by slice (within the
  // reorder lag of each other), while a fifth reads the getters.
  const double t0 = in.imu.front().t, t1 = in.imu.back().t + 1.0;
  Slices slices(4);
  const auto feeder = [&](auto& samples, auto add) {
    return [&samples, add, &slices, t0, t1] {
      size_t k = 0;
      for (double t = t0; t < t1; t += 0.1) {
        while (k < samples.size() && samples[k].t < t + 0.1) add(samples[k++]);
        slices.arrive();
      }
    };
  };
  std::atomic<bool> done{false};
  std::atomic<long> reads{0};
  std::thread reader([&] {
    while (!done) {
      const CalibratorHealth h = queue.health();
      const auto c = queue.calibration();
      if (c) {
        EXPECT_TRUE(c->cov.allFinite());
      }
      reads += h.t_data >= 0.0;
      // As a robot's monitor reads: often, not spinning (a spinning reader starves the drivers
      // on a two-core machine, and under qemu for minutes).
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  std::vector<std::thread> drivers;
  drivers.emplace_back(feeder(in.imu, [&](const ImuSample& s) { queue.addImu(s); }));
  drivers.emplace_back(feeder(in.odom, [&](const OdomSample& s) { queue.addOdometer(s); }));
  drivers.emplace_back(feeder(in.rover.epochs, [&](const ObsEpoch& e) { queue.addRover(e); }));
  drivers.emplace_back(feeder(in.base.epochs, [&](const ObsEpoch& e) { queue.addBase(e); }));
  for (std::thread& d : drivers) d.join();
  queue.finish();
  done = true;
  reader.join();
  EXPECT_GT(reads.load(), 0);
  const CalibrationRun& run = queue.calibrator().run();
  EXPECT_EQ(run.counter(Counter::kLateSamples), 0);
  ASSERT_TRUE(run.latest);
  EXPECT_EQ(run.final().calib.p_b_m, ordered.final().calib.p_b_m);
  EXPECT_EQ(run.final().calib.s_v, ordered.final().calib.s_v);
  EXPECT_EQ(run.final().cov, ordered.final().cov);
  EXPECT_EQ(queue.calibration()->t, ordered.final().t);
}

}  // namespace
}  // namespace giocal
