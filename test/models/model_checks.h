// Generic checks of a MeasurementModel: Jacobians against numeric differentiation in the tangent
// space of each block.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "common/math/rotation.h"
#include "common/models/measurement_model.h"
#include "numeric_jacobian.h"

namespace giocal::test {

/// A random value of block b: components uniform in +-scale (a rotation by such angles).
inline Eigen::VectorXd randomBlockValue(const StateBlock& b, double scale, std::mt19937& gen) {
  std::uniform_real_distribution<double> u(-scale, scale);
  auto draw = [&] { return u(gen); };
  if (b.kind == BlockKind::kRotation) {
    Eigen::VectorXd q(4);
    quatToWxyz(Quat(expSO3(Vec3(draw(), draw(), draw()))), q.data());
    return q;
  }
  Eigen::VectorXd v(b.size);
  for (int i = 0; i < b.size; ++i) v[i] = draw();
  return v;
}

/// values[k] holds block k's ambient values.
inline std::vector<const double*> pointers(const std::vector<Eigen::VectorXd>& values) {
  std::vector<const double*> p;
  for (const auto& v : values) p.push_back(v.data());
  return p;
}

/// Block value plus a tangent perturbation.
inline Eigen::VectorXd perturbBlock(const StateBlock& b, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& d) {
  if (b.kind == BlockKind::kVector) return x + d;
  Eigen::VectorXd out(4);
  quatToWxyz(boxPlus(quatFromWxyz(x.data()), Eigen::Vector3d(d)), out.data());
  return out;
}

/// `step`: the central-difference step; models whose residuals are differences of large numbers
/// (GNSS ranges of 2e7 m carry 4e-9 m of rounding) need a larger one.
inline void expectJacobiansMatchNumeric(const MeasurementModel& model,
                                        const std::vector<Eigen::VectorXd>& values, double tol,
                                        double step = 1e-6) {
  Eigen::VectorXd r;
  std::vector<Eigen::MatrixXd> J;
  model.evaluate(pointers(values).data(), r, &J);
  ASSERT_EQ(r.size(), model.residualSize());
  ASSERT_EQ(J.size(), model.blocks().size());
  for (size_t k = 0; k < model.blocks().size(); ++k) {
    const StateBlock& b = model.blocks()[k];
    ASSERT_EQ(J[k].rows(), model.residualSize()) << b.key.str();
    ASSERT_EQ(J[k].cols(), b.tangentSize()) << b.key.str();
    const auto f = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
      std::vector<Eigen::VectorXd> v = values;
      v[k] = perturbBlock(b, values[k], d);
      Eigen::VectorXd out;
      model.evaluate(pointers(v).data(), out, nullptr);
      return out;
    };
    EXPECT_LT(relativeDifference(J[k], numericJacobian(f, b.tangentSize(), step)), tol)
        << model.name() << " block " << b.key.str();
  }
}

}  // namespace giocal::test
