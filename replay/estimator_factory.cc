#include "replay/estimator_factory.h"

#include <stdexcept>

#include "ekf/ekf_core.h"
#if GIOCAL_FACTOR_GRAPH
#include "fgo/factor_graph_core.h"
#endif

namespace giocal {

std::vector<std::string> estimatorNames() {
#if GIOCAL_FACTOR_GRAPH
  return {"ekf", "fgo"};
#else
  return {"ekf"};
#endif
}

CoreFactory coreFactory(const std::string& name, const CalibrationOptions& options,
                        const FgoOptions& fgo_options) {
  if (name == "ekf") {
    return [options](const CalibrationInputs& sensors, const BroadcastOrbits& orbits,
                     const InitialState& init) -> std::unique_ptr<EstimatorCore> {
      return std::make_unique<EkfCore>(options, sensors, orbits, init);
    };
  }
#if GIOCAL_FACTOR_GRAPH
  if (name == "fgo") {
    return [options, fgo_options](const CalibrationInputs& sensors, const BroadcastOrbits& orbits,
                                  const InitialState& init) -> std::unique_ptr<EstimatorCore> {
      return std::make_unique<FactorGraphCore>(sensors, orbits, options, fgo_options, init);
    };
  }
  throw std::invalid_argument("--estimator must be ekf or fgo, not '" + name + "'");
#else
  (void)fgo_options;
  if (name == "fgo") {
    throw std::invalid_argument(
        "--estimator fgo: this giocal was built without the factor graph "
        "(-DGIOCAL_FACTOR_GRAPH=OFF); the EKF is --estimator ekf");
  }
  throw std::invalid_argument("--estimator must be ekf, not '" + name + "'");
#endif
}

std::unique_ptr<Calibrator> makeCalibrator(const std::string& name,
                                           const DatasetDescription& dataset,
                                           const Eigen::Vector3d& base_e,
                                           const CalibrationOptions& options,
                                           const FgoOptions& fgo_options, RunSink* sink) {
  return std::make_unique<Calibrator>(name, dataset, base_e, options,
                                      coreFactory(name, options, fgo_options), sink);
}

}  // namespace giocal
