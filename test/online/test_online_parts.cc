#include <gtest/gtest.h>

#include <deque>
#include <type_traits>
#include <vector>

#include "common/containers/ring_queue.h"
#include "common/online/convergence.h"
#include "common/online/latency_histogram.h"
#include "common/online/reorder_buffer.h"
#include "replay/estimator_factory.h"

namespace giocal {
namespace {

TEST(RingQueue, KeepsOrderThroughWrapsGrowthAndInserts) {
  RingQueue<int> q;
  std::deque<int> expected;  // the reference
  for (int k = 0; k < 1000; ++k) {
    q.push_back(k);
    expected.push_back(k);
    if (k % 3 == 0) {  // a late item two places from the back
      const size_t at = q.size() >= 2 ? q.size() - 2 : 0;
      q.insert(at, -k);
      expected.insert(expected.begin() + static_cast<long>(at), -k);
    }
    while (q.size() > 20) {  // a bounded window: the front leaves as the back grows
      ASSERT_EQ(q.front(), expected.front());
      q.pop_front();
      expected.pop_front();
    }
    ASSERT_EQ(q.size(), expected.size());
    for (size_t i = 0; i < q.size(); ++i) ASSERT_EQ(q[i], expected[i]) << k << " " << i;
    ASSERT_EQ(q.back(), expected.back());
  }
  q.clear();
  EXPECT_TRUE(q.empty());
  // Items that own memory leave nothing behind when they leave the queue.
  RingQueue<std::vector<double>> v;
  v.push_back(std::vector<double>(100, 1.0));
  v.push_back(std::vector<double>(5, 2.0));
  v.pop_front();
  EXPECT_EQ(v.front(), std::vector<double>(5, 2.0));
}

TEST(ReorderBuffer, ReleasesInTimeOrderAfterTheLagAndRefusesThePast) {
  ReorderBuffer<int> b(0.5);
  std::vector<double> out;
  const auto take = [&](double t, int&) { out.push_back(t); };
  EXPECT_TRUE(b.push(1.0, 0));
  EXPECT_TRUE(b.push(0.8, 0));  // arrived late but within the lag
  b.release(take);
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(b.push(1.4, 0));
  b.release(take);
  EXPECT_EQ(out, std::vector<double>({0.8}));
  EXPECT_TRUE(b.push(2.0, 0));
  b.release(take);
  EXPECT_EQ(out, std::vector<double>({0.8, 1.0, 1.4}));
  EXPECT_FALSE(b.push(1.2, 0));  // before what was released: refused
  EXPECT_FALSE(b.push(NAN, 0));
  b.release(take, true);
  EXPECT_EQ(out, std::vector<double>({0.8, 1.0, 1.4, 2.0}));
}

TEST(ReorderBuffer, EqualTimesLeaveInArrivalOrderAndALateDatumFindsItsPlace) {
  ReorderBuffer<int> b(1.0);
  std::vector<int> out;
  const auto take = [&](double, int& v) { out.push_back(v); };
  for (const auto& [t, v] : std::vector<std::pair<double, int>>{
           {1.0, 1}, {1.0, 2}, {1.5, 4}, {1.2, 3}, {1.0, 10}, {0.5, 0}, {1.5, 5}}) {
    EXPECT_TRUE(b.push(t, v));
  }
  b.release(take, true);
  EXPECT_EQ(out, std::vector<int>({0, 1, 2, 10, 3, 4, 5}));
  EXPECT_EQ(b.size(), 0u);
}

CalibrationEstimate estimate(double t, double s_v, double sd_s_v) {
  CalibrationEstimate e;
  e.t = t;
  e.calib.s_v = s_v;
  e.cov = Eigen::Matrix<double, 8, 8>::Identity();  // every other state far from its target
  e.cov(0, 0) = sd_s_v * sd_s_v;
  return e;
}

TEST(ConvergenceMonitor, ConvergesWhenTheSigmaIsSmallAndTheValueSteadyOverTheTime) {
  ConvergenceOptions o;
  o.sigma_scale = 1e-3;
  o.steady_s = 10.0;
  ConvergenceMonitor m(o, {4});  // p_b_m.z held
  // Sigma below target from t = 5, but the value still moves until t = 20.
  std::vector<ConvergenceEvent> events;
  for (int t = 0; t <= 40; ++t) {
    const double value = t < 20 ? 0.01 * t : 0.2;
    for (const auto& e : m.update(estimate(t, value, t < 5 ? 1e-2 : 5e-4))) events.push_back(e);
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].state, 0);
  EXPECT_TRUE(events[0].converged);
  EXPECT_DOUBLE_EQ(events[0].t, 30.0);  // 10 s after the value stopped moving
  EXPECT_DOUBLE_EQ(m.convergedAt(0), 30.0);
  EXPECT_FALSE(m.done());        // the others never did
  EXPECT_FALSE(m.takesPart(4));  // p_b_m.z held
  // A re-opened covariance undoes it.
  const auto lost = m.update(estimate(41, 0.2, 5e-3));
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_FALSE(lost[0].converged);
}

// The estimator cores hold references into the calibrator's buffers: a copy or a move would
// leave them dangling, so neither compiles. The frame of navState() has its origin exposed.
static_assert(!std::is_copy_constructible_v<Calibrator> &&
                  !std::is_move_constructible_v<Calibrator>,
              "Calibrator must be neither copied nor moved");
static_assert(!std::is_copy_assignable_v<Calibrator> && !std::is_move_assignable_v<Calibrator>,
              "Calibrator must be neither copied nor moved");
TEST(Calibrator, NoNavigationStateOrOriginBeforeTheFirstInitialization) {
  const auto cal = makeCalibrator("ekf", DatasetDescription{}, Eigen::Vector3d::Zero(),
                                  CalibrationOptions{}, {}, nullptr);
  EXPECT_FALSE(cal->navState().has_value());
  EXPECT_EQ(cal->navOriginEcef(), Eigen::Vector3d::Zero());
}

TEST(LatencyHistogram, PercentilesWithinTheBinWidth) {
  LatencyHistogram h;
  for (int k = 1; k <= 1000; ++k) h.add(k * 1e-4);  // 0.1 ms .. 100 ms
  EXPECT_NEAR(h.mean(), 0.05005, 1e-9);
  EXPECT_DOUBLE_EQ(h.max(), 0.1);
  EXPECT_NEAR(h.percentile(0.5), 0.05, 0.05 * 0.06);
  EXPECT_NEAR(h.percentile(0.99), 0.099, 0.099 * 0.06);
}

}  // namespace
}  // namespace giocal
