#include "ekf/single_receiver_update.h"

#include <cmath>

#include "common/gnss/tdcp_track.h"
#include "common/math/rotation.h"
#include "common/models/position_model.h"
#include "common/models/tdcp_model.h"
#include "ekf/doppler_update.h"

namespace giocal {

namespace {

// The antenna position (ECEF) of the pose (p, q) through the lever arm.
Eigen::Vector3d antennaAt(const CalibrationFilter& f, const StateKey& p, const StateKey& q) {
  const StateRegistry& s = f.state();
  const Eigen::Quaterniond R = quatFromWxyz(s.value(q).data());
  return f.frame().ecefFromEnu(s.value(p) + R * s.value(state::kPbg));
}

// The standard deviation of the position's change since the clone: sqrt of the trace of
// P_now + P_clone - 2 sym(P_cross) (the attitude's share through the lever arm is centimetres
// at most and left to the gate's margin).
double displacementSigma(const StateRegistry& s) {
  const int a = s.offset(state::kP), b = s.offset(kGnssP);
  const Eigen::MatrixXd& P = s.covariance();
  const Eigen::Matrix3d C =
      P.block<3, 3>(a, a) + P.block<3, 3>(b, b) - P.block<3, 3>(a, b) - P.block<3, 3>(b, a);
  return std::sqrt(std::max(C.trace(), 0.0));
}

// A first-order Gauss-Markov 3-vector `key` carried from `t_at` to t (then t_at = t), with
// stationary covariance Q: added at zero with Q where the state has none yet; else x <- phi x + w,
// the block's rows and columns scaled by phi and Q filling what the decay left
// (phi^2 P + (1 - phi^2) Q).
void carryGaussMarkov(StateRegistry& s, const StateKey& key, double t, double tau_s,
                      const Eigen::Matrix3d& Q, double& t_at) {
  if (!s.has(key)) {
    s.add(vectorBlock(key), Eigen::Vector3d::Zero(), Q);
    t_at = t;
    return;
  }
  const double phi = std::exp(-std::max(t - t_at, 0.0) / tau_s);
  t_at = t;
  const int i = s.offset(key);
  s.value(key) *= phi;
  Eigen::MatrixXd& P = s.covariance();
  P.middleRows(i, 3) *= phi;
  P.middleCols(i, 3) *= phi;
  P.block<3, 3>(i, i) += (1.0 - phi * phi) * Q;
}

}  // namespace

SingleReceiverUpdate::SingleReceiverUpdate(const BroadcastOrbits& orbits,
                                           const CalibrationOptions& options)
    : orbits_(orbits), options_(options), builder_(orbits, options.single.tdcp) {}

GnssEpochReport SingleReceiverUpdate::process(CalibrationFilter& f, const ObsEpoch& rover) {
  GnssEpochReport rep;
  f.propagateTo(rover.t);
  StateRegistry& s = f.state();
  const double dt = std::isnan(t_last_) ? 0.0 : rover.t - t_last_;
  t_last_ = rover.t;
  const Eigen::Vector3d ant_e = antennaAt(f, state::kP, state::kQ);
  TdcpPair pair = builder_.add(rover, ant_e);
  rep.tdcp_slips =
      static_cast<int>(pair.left_out.slipped + pair.left_out.half_cycle + pair.left_out.broken);
  // The clone stands for the pair's first epoch only if it was taken there.
  if (s.has(kGnssP) && !pair.rows.empty() && std::abs(clone_t_ - pair.t0) < 1e-6)
    rep.tdcp_rows = updateTdcp(f, std::move(pair), rep);
  const DopplerRows doppler = updateDoppler(f, orbits_, options_, rover, ant_e, {}, dt);
  rep.rejected_rows += doppler.rejected;
  rep.doppler_rows = doppler.used;
  const SppSolution spp = solveSpp(rover, orbits_, sppOnSkyOf(options_.single.tdcp));
  const bool positioned = spp.valid && updatePosition(f, spp);
  rep.used = rep.tdcp_rows > 0 || positioned;
  // The pose here is the next pair's first.
  for (const StateKey& k : {kGnssP, kGnssQ}) {
    if (s.has(k)) s.remove(k);
  }
  s.clone(state::kP, kGnssP);
  s.clone(state::kQ, kGnssQ);
  clone_t_ = rover.t;
  return rep;
}

int SingleReceiverUpdate::updateTdcp(CalibrationFilter& f, TdcpPair pair, GnssEpochReport& rep) {
  StateRegistry& s = f.state();
  const int screened =
      screenTdcp(pair, antennaAt(f, kGnssP, kGnssQ), antennaAt(f, state::kP, state::kQ),
                 displacementSigma(s), options_.single.tdcp_screen_gate);
  rep.tdcp_screened = screened;
  std::vector<StateKey> keys{kGnssP, kGnssQ, state::kP, state::kQ, state::kPbg};
  const bool drift = options_.single.tdcp_drift_sigma > 0 &&
                     advanceDrift(f, pair, antennaAt(f, state::kP, state::kQ));
  if (drift) keys.push_back(state::kTdcpDrift);
  while (pair.rows.size() >= 3) {
    const TdcpModel model(f.frame(), pair, drift);
    const Eigen::VectorXd z =
        normalizedInnovations(s.covariance(), linearize(model, s.bind(keys), s.dim()));
    long worst = 0;
    if (z.maxCoeff(&worst) <= options_.innovation_gate) {
      const int rows = static_cast<int>(pair.rows.size());
      return f.update(model, keys, INFINITY).accepted ? rows : 0;
    }
    dropRowSignal(pair, worst);
    ++rep.rejected_rows;
  }
  return 0;
}

bool SingleReceiverUpdate::advanceDrift(CalibrationFilter& f, const TdcpPair& pair,
                                        const Eigen::Vector3d& ant_e) {
  StateRegistry& s = f.state();
  const Eigen::Matrix3d Q =
      tdcpDriftCovariance(f.frame(), pair, ant_e, options_.single.tdcp_drift_sigma);
  const bool known = s.has(state::kTdcpDrift);
  if (!Q.allFinite()) return known;  // kept as it is until a sky fixes it again
  carryGaussMarkov(s, state::kTdcpDrift, pair.t1, options_.single.tdcp_drift_tau_s, Q, drift_t_);
  return true;
}

bool SingleReceiverUpdate::updatePosition(CalibrationFilter& f, const SppSolution& spp) {
  const PositionFix fix = sppFix(spp, f.time(), options_.single.position_sigma_min_m);
  if (options_.single.spp_bias_sigma > 0) {
    advanceSppBias(f, sppBiasCovariance(f.frame(), spp, options_.single.spp_bias_sigma));
    return f
        .update(positionModelOf(f.frame(), fix, PositionWeighting{}).withBias(),
                {state::kP, state::kQ, state::kPbg, state::kSppBias},
                chi2Quantile(options_.chi2_probability, 3))
        .accepted;
  }
  const PositionModel model = positionModelOf(f.frame(), fix, PositionWeighting{});
  return f
      .update(model, {state::kP, state::kQ, state::kPbg},
              chi2Quantile(options_.chi2_probability, 3))
      .accepted;
}

void SingleReceiverUpdate::advanceSppBias(CalibrationFilter& f, const Eigen::Matrix3d& Q) {
  carryGaussMarkov(f.state(), state::kSppBias, f.time(), options_.single.spp_bias_tau_s, Q,
                   spp_bias_t_);
}

}  // namespace giocal
