#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/gnss/double_difference.h"

namespace giocal {
namespace {

// ddCovariance against its definition: a DD row's variance is its satellite's plus its
// reference's single-difference variance, and two rows covary by the reference's variance when
// they share the reference, the band and the kind (code or phase). Rows of one group are
// interleaved with others, as a builder that orders by satellite leaves them.
TEST(DdCovariance, RowsCovaryExactlyWhenTheyShareReferenceBandAndKind) {
  const SatId g1{GnssSystem::kGps, 1}, g2{GnssSystem::kGps, 2}, g3{GnssSystem::kGps, 3};
  const SatId e1{GnssSystem::kGalileo, 1}, e2{GnssSystem::kGalileo, 2};
  // Geometry indices: 0 g1, 1 g2, 2 g3, 3 e1, 4 e2; variances (code, phase) distinct per index.
  std::vector<std::pair<double, double>> var;
  for (int i = 0; i < 5; ++i) var.push_back({1.0 + i, 0.01 * (1 + i)});
  std::vector<DdObservation> obs;
  const auto row = [&](SatId s, int si, SatId r, int ri, char band, bool phase) {
    DdObservation o;
    o.sat = s;
    o.ref = r;
    o.band = band;
    o.phase = phase;
    o.sat_index = si;
    o.ref_index = ri;
    obs.push_back(o);
  };
  row(g2, 1, g1, 0, '1', false);
  row(e2, 4, e1, 3, '1', false);
  row(g2, 1, g1, 0, '1', true);
  row(g3, 2, g1, 0, '1', false);  // shares g1, L1, code with row 0
  row(g3, 2, g1, 0, '2', false);  // another band
  row(g3, 2, g1, 0, '1', true);   // shares g1, L1, phase with row 2
  row(g1, 0, g2, 1, '1', false);  // another reference
  const Eigen::MatrixXd R = ddCovariance(obs, var);
  ASSERT_EQ(R.rows(), 7);
  for (size_t a = 0; a < obs.size(); ++a) {
    for (size_t b = 0; b < obs.size(); ++b) {
      const DdObservation &x = obs[a], &y = obs[b];
      const auto v = [&](int i) { return x.phase ? var[i].second : var[i].first; };
      double expected = a == b ? v(x.sat_index) : 0.0;
      if (x.ref == y.ref && x.band == y.band && x.phase == y.phase) expected += v(x.ref_index);
      EXPECT_EQ(R(a, b), expected) << a << "," << b;
    }
  }
  EXPECT_EQ(R(0, 3), 1.0);  // g1's code variance
  EXPECT_EQ(R(2, 5), 0.01);
  EXPECT_EQ(R(0, 4), 0.0);
}

}  // namespace
}  // namespace giocal
