// The factor graph's single-receiver factors (no base): time-differenced carrier phase linking
// the epoch's pose with the previous epoch's (screened against the IMU's prediction, then rows
// left out after the solve while beyond the rejection sigma), Doppler with the clock drift, and
// the single point position with a loose weight and its slow offset (a variable per epoch).
#include <cmath>

#include "common/gnss/spp.h"
#include "common/gnss/tdcp_track.h"
#include "common/imu/gyro_mean.h"
#include "common/models/position_model.h"
#include "common/models/prior_model.h"
#include "common/models/random_walk_model.h"
#include "common/models/tdcp_model.h"
#include "fgo/factor_graph_core.h"
#include "fgo/factor_tag.h"

namespace giocal {

using fgo_tag::tagged;
using state::kPbg;

namespace {

// The IMU's prediction of one epoch's displacement from the solved epoch before it, 1-sigma:
// centimetres over the second between epochs (the factor graph keeps no covariance to ask).
constexpr double kPredictedDisplacementSigma_m = 0.05;

}  // namespace

Eigen::Vector3d FactorGraphCore::antennaOf(const FgoEpoch& e) const {
  const NavState x = nav(e);
  return frame_.ecefFromEnu(x.p_n_b + x.q_n_b * w_.value(kPbg));
}

void FactorGraphCore::singleFactors(FgoEpoch& e, const FgoEpoch& prev, const ObsEpoch& rover) {
  const Eigen::Vector3d ant_e = antennaOf(e);
  e.tdcp = tdcp_.add(rover, ant_e);
  run_->count(Counter::kTdcpSlips,
              e.tdcp.left_out.slipped + e.tdcp.left_out.half_cycle + e.tdcp.left_out.broken);
  for (const SatId& sat : tdcp_.takeNewlyBroken())
    run_->warn(brokenSatelliteWarning(sat, o_.single.tdcp.max_slips_in_a_row, e.t));
  if (e.tdcp.rows.empty() || std::abs(prev.t - e.tdcp.t0) > 1e-6) {
    e.tdcp.rows.clear();
  } else {
    run_->count(Counter::kTdcpScreened,
                screenTdcp(e.tdcp, antennaOf(prev), ant_e, kPredictedDisplacementSigma_m,
                           o_.single.tdcp_screen_gate));
    if (e.tdcp.rows.size() < 3) e.tdcp.rows.clear();
  }
  const SppSolution spp = solveSpp(rover, orbits_, sppOnSkyOf(o_.single.tdcp));
  if (o_.single.spp_bias_sigma > 0) {
    if (spp.valid) {
      spp_bias_covariance_ = sppBiasCovariance(frame_, spp, o_.single.spp_bias_sigma);
    }
    addSppBias(e, prev);
  }
  if (spp.valid) {
    const PositionFix fix = sppFix(spp, e.t, o_.single.position_sigma_min_m);
    const PositionModel model = positionModelOf(frame_, fix, PositionWeighting{});
    if (e.spp_bias) {
      w_.addFactor({std::make_shared<PositionModel>(model.withBias()),
                    {e.p, e.q, kPbg, e.bs},
                    fo_.code_huber,
                    tagged("position", e.k)});
    } else {
      w_.addFactor({std::make_shared<PositionModel>(model),
                    {e.p, e.q, kPbg},
                    fo_.code_huber,
                    tagged("position", e.k)});
    }
  }
  e.gyro = meanGyro(in_.imu, e.t, 0.5 * o_.models.motion.window_s,
                    in_.description.imu_noise.gyro_noise_density)
               .rate;
  e.doppler = dopplerObservations(rover, orbits_, ant_e, o_.doppler, {});
  startClockDrift(e);
  addGnssRowFactors(e);
  if (o_.single.tdcp_drift_sigma > 0) addDrift(e, prev, ant_e);
  addTdcpFactor(e, prev);
}

void FactorGraphCore::addDrift(FgoEpoch& e, const FgoEpoch& prev, const Eigen::Vector3d& ant_e) {
  if (!e.tdcp.rows.empty()) {
    const Eigen::Matrix3d Q =
        tdcpDriftCovariance(frame_, e.tdcp, ant_e, o_.single.tdcp_drift_sigma);
    if (Q.allFinite()) drift_covariance_ = Q;
  }
  if (!drift_covariance_.allFinite()) return;  // no sky has fixed one yet
  e.drift = true;
  addGaussMarkov(e, prev.drift ? &prev.vt : nullptr, e.vt, prev.t, o_.single.tdcp_drift_tau_s,
                 drift_covariance_, "drift", "drift_prior");
}

void FactorGraphCore::addSppBias(FgoEpoch& e, const FgoEpoch& prev) {
  if (!spp_bias_covariance_.allFinite()) return;  // no solution has given one yet
  e.spp_bias = true;
  addGaussMarkov(e, prev.spp_bias ? &prev.bs : nullptr, e.bs, prev.t, o_.single.spp_bias_tau_s,
                 spp_bias_covariance_, "spp_bias", "spp_bias_prior");
}

void FactorGraphCore::addGaussMarkov(const FgoEpoch& e, const StateKey* before, const StateKey& now,
                                     double t_before, double tau_s, const Eigen::Matrix3d& Q,
                                     const char* tag, const char* prior_tag) {
  if (!before) {
    w_.addVariable(vectorBlock(now), Eigen::Vector3d::Zero());
    w_.addFactor({std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(now)},
                                               Eigen::VectorXd::Zero(3), Q),
                  {now},
                  0.0,
                  tagged(prior_tag, e.k)});
    return;
  }
  const double phi = std::exp(-(e.t - t_before) / tau_s);
  w_.addVariable(vectorBlock(now), phi * w_.value(*before));
  w_.addFactor({std::make_shared<RandomWalkModel>(StateKey{now.what}, phi, (1.0 - phi * phi) * Q),
                {*before, now},
                0.0,
                tagged(tag, e.k)});
}

void FactorGraphCore::addTdcpFactor(const FgoEpoch& e, const FgoEpoch& prev) {
  w_.removeFactors(tagged("tdcp", e.k));
  if (e.tdcp.rows.empty()) return;
  std::vector<StateKey> vars{prev.p, prev.q, e.p, e.q, kPbg};
  if (e.drift) vars.push_back(e.vt);
  w_.addFactor(
      {std::make_shared<TdcpModel>(frame_, e.tdcp, e.drift), vars, 0.0, tagged("tdcp", e.k)});
}

bool FactorGraphCore::rejectWorstTdcp(FgoEpoch& e, const FgoEpoch& prev) {
  if (e.tdcp.rows.empty()) return false;
  const TdcpModel m(frame_, e.tdcp, e.drift);
  const double* params[6] = {w_.value(prev.p).data(), w_.value(prev.q).data(),
                             w_.value(e.p).data(),    w_.value(e.q).data(),
                             w_.value(kPbg).data(),   e.drift ? w_.value(e.vt).data() : nullptr};
  Eigen::VectorXd r;
  m.evaluate(params, r, nullptr);
  const Eigen::VectorXd z = r.cwiseAbs().cwiseQuotient(m.covariance().diagonal().cwiseSqrt());
  long worst = 0;
  if (z.maxCoeff(&worst) <= fo_.rejection_sigma) return false;
  run_->count(Counter::kGnssRowsRejected);
  dropRowSignal(e.tdcp, worst);
  addTdcpFactor(e, prev);
  return true;
}

}  // namespace giocal
