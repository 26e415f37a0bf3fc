// The ceiling of ambiguity resolution on a simulated dataset (issue 23, item 5): every epoch
// "fixed" with the true integers (rounded from the DD phase at the true antenna), the position
// solved from the phase rows alone, and its horizontal error against the true antenna. A correct
// fix is still wrong by the audit's 5 cm criterion where the sky's geometry and the errors the
// model does not know put it there; no ambiguity resolution of one epoch's GNSS does better
// than the true integers.
// Usage: giocal_fix_ceiling --data <simulated dataset> [--data <another> ...] [--threshold-m 0.05]
//                           [--gate-m 0.02]
// Prints over all datasets, per scene: epochs, epochs with four satellites, the share of those more
// than the threshold off, the rate and wrong share within the horizontal-sigma gate, and the
// largest fix rate (epochs taken by horizontal sigma, smallest first) that keeps the wrong share at
// or below 0.5 %, also among only the epochs whose post-fit residuals pass a chi-square test.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/reference_trajectory.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/rtk.h"
#include "common/gnss/spp.h"
#include "common/io/scenes_csv.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"

using namespace giocal;

namespace {

struct OracleFix {
  double sigma_h = 0.0, error_h = 0.0;
  bool residuals_pass = true;  // the post-fit phase residuals' chi-square within its 99 % bound
};

// Least squares of the antenna from the epoch's phase rows with the integers the true antenna
// gives; none without three independent directions.
std::optional<OracleFix> solveWithTrueIntegers(const DdEpoch& epoch, const Eigen::Vector3d& truth_e,
                                               const Eigen::Matrix3d& R_e_n) {
  std::vector<DdObservation> rows;
  std::vector<double> n_dd;
  for (const DdObservation& o : epoch.obs) {
    if (!o.phase) continue;
    const double n = (o.value - ddPredict(o, epoch.geometry, truth_e, 0, 0, nullptr)) / o.lambda;
    // A row more than a quarter cycle from an integer at the truth has no true integer to take.
    if (std::abs(n - std::round(n)) > 0.25) continue;
    rows.push_back(o);
    n_dd.push_back(std::round(n));
  }
  if (rows.size() < 3) return std::nullopt;
  const Eigen::MatrixXd R = ddCovariance(rows, epoch.undiff_variance);
  const Eigen::LLT<Eigen::MatrixXd> llt(R);
  if (llt.info() != Eigen::Success) return std::nullopt;
  Eigen::Vector3d x = truth_e;
  Eigen::Matrix3d info;
  double chi2 = 0.0;
  for (int it = 0; it < 3; ++it) {
    Eigen::MatrixXd H(static_cast<long>(rows.size()), 3);
    Eigen::VectorXd r(static_cast<long>(rows.size()));
    for (size_t k = 0; k < rows.size(); ++k) {
      Eigen::RowVector3d J;
      r(static_cast<long>(k)) =
          rows[k].value - ddPredict(rows[k], epoch.geometry, x, n_dd[k], 0, &J);
      H.row(static_cast<long>(k)) = J;
    }
    const Eigen::MatrixXd W = llt.matrixL().solve(H);
    const Eigen::VectorXd w = llt.matrixL().solve(r);
    info = W.transpose() * W;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(info);
    if (!(eig.eigenvalues().minCoeff() > 1e-6 * eig.eigenvalues().maxCoeff())) return std::nullopt;
    const Eigen::Vector3d dx = info.ldlt().solve(W.transpose() * w);
    x += dx;
    chi2 = (w - W * dx).squaredNorm();
  }
  const Eigen::Matrix3d cov_n = R_e_n.transpose() * info.inverse() * R_e_n;
  const Eigen::Vector3d d_n = R_e_n.transpose() * (x - truth_e);
  const int dof = static_cast<int>(rows.size()) - 3;
  return OracleFix{std::sqrt(cov_n(0, 0) + cov_n(1, 1)), d_n.head<2>().norm(),
                   dof <= 0 || chi2 <= chi2Quantile(0.99, dof)};
}

struct SceneTally {
  long epochs = 0;
  std::vector<OracleFix> fixes;
};

double wrongShare(const std::vector<OracleFix>& f, size_t n, double threshold) {
  if (n == 0) return 0.0;
  long wrong = 0;
  for (size_t k = 0; k < n; ++k) wrong += f[k].error_h > threshold;
  return static_cast<double>(wrong) / static_cast<double>(n);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> datasets;
  double threshold = 0.05, gate = 0.02;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--data")
      datasets.push_back(argv[i + 1]);
    else if (a == "--threshold-m")
      threshold = std::stod(argv[i + 1]);
    else if (a == "--gate-m")
      gate = std::stod(argv[i + 1]);
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  if (datasets.empty()) {
    std::cerr << "usage: giocal_fix_ceiling --data <simulated dataset>\n";
    return 2;
  }
  try {
    std::map<std::string, SceneTally> by_scene;
    for (const std::string& data : datasets) {
      const CalibrationInputs in = loadCalibrationInputs(data);
      if (!in.truth || in.description.truth.empty())
        throw std::runtime_error(data + ": needs truth.csv and truth_calib.yaml");
      const ReferenceTrajectory truth(readTruthCsv(in.description.pathOf(in.description.truth)));
      const std::vector<SceneSpan> scenes = readScenesCsv(data + "/scenes.csv");
      const RtkOptions rtk;  // giocal rtk's defaults: mask, frequencies, systems, noise
      const BroadcastOrbits orbits(in.nav);
      DdEpochBuilder builder(orbits, in.base_e, rtk.dd);
      BaseEpochMatcher base(in.base.epochs, rtk.max_base_offset);
      for (const ObsEpoch& rover : in.rover.epochs) {
        const std::optional<TruthSample> s = truth.at(rover.t);
        const ObsEpoch* b = base.nearest(rover.t);
        const std::string scene = sceneAt(scenes, rover.t);
        if (!s || !b || scene.empty()) continue;
        const double lat = s->lat_deg * kDegToRad, lon = s->lon_deg * kDegToRad;
        const Eigen::Matrix3d R_e_n = rotationEcefFromEnu(lat, lon);
        const Eigen::Vector3d antenna_e =
            ecefFromGeodetic({lat, lon, s->h}) + R_e_n * (s->q_n_b * in.truth->p_b_g);
        SceneTally& tally = by_scene[scene];
        ++tally.epochs;
        const auto fix =
            solveWithTrueIntegers(builder.build(rover, *b, antenna_e), antenna_e, R_e_n);
        if (fix) tally.fixes.push_back(*fix);
      }
    }
    std::cout << "scene epochs 4sats wrong% | gated% wrong% | best_rate%@0.5%wrong by_sigma "
                 "with_residual_test\n"
              << std::fixed << std::setprecision(2);
    for (auto& [scene, tally] : by_scene) {
      std::vector<OracleFix>& f = tally.fixes;
      std::sort(f.begin(), f.end(),
                [](const OracleFix& a, const OracleFix& b) { return a.sigma_h < b.sigma_h; });
      const size_t gated = static_cast<size_t>(
          std::count_if(f.begin(), f.end(), [&](const OracleFix& x) { return x.sigma_h <= gate; }));
      size_t best = 0;
      for (size_t n = 1; n <= f.size(); ++n)
        if (wrongShare(f, n, threshold) <= 0.005) best = n;
      // The same, among the epochs whose residuals pass: a second test on what the data show.
      std::vector<OracleFix> passing;
      for (const OracleFix& x : f)
        if (x.residuals_pass) passing.push_back(x);
      size_t best_passing = 0;
      for (size_t n = 1; n <= passing.size(); ++n)
        if (wrongShare(passing, n, threshold) <= 0.005) best_passing = n;
      const double e = static_cast<double>(tally.epochs);
      std::cout << scene << " " << tally.epochs << " " << f.size() << " "
                << 100.0 * wrongShare(f, f.size(), threshold) << " | "
                << 100.0 * static_cast<double>(gated) / e << " "
                << 100.0 * wrongShare(f, gated, threshold) << " | "
                << 100.0 * static_cast<double>(best) / e << " "
                << 100.0 * static_cast<double>(best_passing) / e << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
