#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/multipath.h"

namespace giocal::sim {
namespace {

struct Moments {
  double variance = 0.0, lag1 = 0.0;  // lag1: the correlation of consecutive samples
};

Moments momentsOf(const std::vector<double>& x) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double var = 0.0, cov = 0.0;
  for (size_t k = 0; k < x.size(); ++k) {
    var += (x[k] - mean) * (x[k] - mean);
    if (k + 1 < x.size()) cov += (x[k] - mean) * (x[k + 1] - mean);
  }
  return {var / static_cast<double>(x.size()), cov / var};
}

// A first-order Gauss-Markov process sampled at 1 s with a 10 s correlation time: stationary
// sigma as asked (times the elevation factor), consecutive samples correlated by exp(-1/10),
// and another satellite's process independent of it.
TEST(Multipath, IsAGaussMarkovProcessWithItsSigmaAndCorrelationTime) {
  MultipathSpec spec;
  spec.code_sigma = 0.4;
  spec.phase_sigma = 0.002;
  spec.tau_s = 10.0;
  Multipath mp(spec, 11);
  const SatId g1{GnssSystem::kGps, 1}, g2{GnssSystem::kGps, 2};
  std::vector<double> code, phase, other;
  for (int k = 0; k < 40000; ++k) {
    const double t = static_cast<double>(k);
    const MultipathError a = mp.at(0, g1, '1', t, 2.0);
    code.push_back(a.code);
    phase.push_back(a.phase);
    other.push_back(mp.at(0, g2, '1', t, 2.0).code);
  }
  const Moments c = momentsOf(code), p = momentsOf(phase);
  EXPECT_NEAR(std::sqrt(c.variance), 0.8, 0.04);  // 0.4 m times the factor 2
  EXPECT_NEAR(std::sqrt(p.variance), 0.004, 0.0002);
  EXPECT_NEAR(c.lag1, std::exp(-0.1), 0.01);
  EXPECT_NEAR(p.lag1, std::exp(-0.1), 0.01);
  double cross = 0.0;
  for (size_t k = 0; k < code.size(); ++k) cross += code[k] * other[k];
  cross /= static_cast<double>(code.size()) * 0.64;
  EXPECT_LT(std::abs(cross), 0.1);  // ~0.02 expected for 2000 independent correlation times
}

TEST(Multipath, OffDrawsNothing) {
  Multipath mp(MultipathSpec{}, 3);
  const MultipathError e = mp.at(1, SatId{GnssSystem::kGalileo, 5}, '7', 10.0, 3.0);
  EXPECT_EQ(e.code, 0.0);
  EXPECT_EQ(e.phase, 0.0);
}

}  // namespace
}  // namespace giocal::sim
