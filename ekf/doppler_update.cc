#include "ekf/doppler_update.h"

#include <cmath>
#include <numeric>

#include "common/math/median.h"
#include "common/math/row_compression.h"
#include "common/models/doppler_model.h"

namespace giocal {

DopplerRows updateDoppler(CalibrationFilter& f, const BroadcastOrbits& orbits,
                          const CalibrationOptions& options, const ObsEpoch& rover,
                          const Eigen::Vector3d& ant_e, const std::vector<RoverSatellite>& known,
                          double dt) {
  DopplerRows rows;
  std::vector<DopplerObservation> obs =
      dopplerObservations(rover, orbits, ant_e, options.doppler, known);
  if (obs.size() < 4) return rows;
  StateRegistry& s = f.state();
  const CalibrationFilter::Gyro gyro = f.gyroAt(rover.t);
  const std::vector<StateKey> keys{state::kV, state::kQ, state::kBg, state::kPbg,
                                   state::kClockDrift};
  if (!s.has(state::kClockDrift) || dt > 30.0) {
    // Start the clock drift from the median residual at zero drift.
    if (s.has(state::kClockDrift)) s.remove(state::kClockDrift);
    s.add(vectorBlock(state::kClockDrift, 1), Eigen::VectorXd::Zero(1),
          Eigen::MatrixXd::Constant(1, 1, 1.0));
    const DopplerModel m(f.frame().R_e_n(), gyro.rate, obs);
    const MeasurementRows lin = linearize(m, s.bind(keys), s.dim());
    s.value(state::kClockDrift)[0] = -median(
        std::vector<double>(lin.residual.data(), lin.residual.data() + lin.residual.size()));
  } else {
    const int i = s.offset(state::kClockDrift);
    s.covariance()(i, i) += options.clock_drift_noise * options.clock_drift_noise * dt;
  }
  while (obs.size() >= 4) {
    const DopplerModel m(f.frame().R_e_n(), gyro.rate, obs);
    const Eigen::VectorXd z =
        normalizedInnovations(s.covariance(), linearize(m, s.bind(keys), s.dim()));
    long worst = 0;
    if (z.maxCoeff(&worst) <= options.innovation_gate) {
      // A row per satellite, on 13 state columns (velocity, attitude, gyro bias, lever arm,
      // clock drift): compressed to those, as the DD code rows.
      std::vector<int> all(obs.size());
      std::iota(all.begin(), all.end(), 0);
      f.updateLinearized(compressRows(f.rows(m, keys, gyro.variance), all), INFINITY);
      rows.used = static_cast<int>(obs.size());
      return rows;
    }
    obs.erase(obs.begin() + worst);
    ++rows.rejected;
  }
  return rows;
}

}  // namespace giocal
