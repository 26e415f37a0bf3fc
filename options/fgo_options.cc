#include "options/fgo_options.h"

#include "common/io/yaml_fields.h"

namespace giocal {

FgoOptions readFgoOptions(const std::string& path) {
  if (path.empty()) return {};
  return readFgoOptions(YamlFields(path));
}

FgoOptions readFgoOptions(const YamlFields& y) {
  FgoOptions o;
  o.window = static_cast<int>(y.numberOr("fgo.window", o.window, 2, 1000));
  o.max_iterations = static_cast<int>(y.numberOr("fgo.max_iterations", o.max_iterations, 1, 1000));
  o.stop_step_sigma = y.numberOr("fgo.stop_step_sigma", o.stop_step_sigma, 0.0, 10.0);
  const std::string solver = y.textOr("fgo.solver", "gauss_newton");
  if (solver == "ceres") {
    o.solver = WindowSolver::kCeres;
  } else if (solver != "gauss_newton") {
    y.fail("fgo.solver", "'" + solver + "' is neither gauss_newton nor ceres");
  }
  o.code_huber = y.numberOr("fgo.code_huber", o.code_huber, 0.0, 1e6);
  o.rejection_sigma = y.numberOr("fgo.rejection_sigma", o.rejection_sigma, 1.0, 1e6);
  o.max_rejections = static_cast<int>(y.numberOr("fgo.max_rejections", o.max_rejections, 0, 100));
  o.odometer_slip_sigma = y.numberOr("fgo.odometer_slip_sigma", o.odometer_slip_sigma, 0.0, 1e6);
  return o;
}

}  // namespace giocal
