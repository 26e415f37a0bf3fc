#include "ekf/model_update.h"

namespace giocal {

UpdateResult updateWithModel(StateRegistry& s, const MeasurementModel& model,
                             const std::vector<std::string>& names, double chi2_gate) {
  const MeasurementRows rows = linearize(model, s.bind(names), s.dim());
  const UpdateResult r = kalmanUpdate(s.covariance(), rows, chi2_gate);
  if (r.accepted) s.correct(r.dx);
  return r;
}

}  // namespace giocal
