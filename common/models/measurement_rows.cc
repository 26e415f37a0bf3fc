#include "common/models/measurement_rows.h"

#include <stdexcept>

namespace giocal {

MeasurementRows linearize(const MeasurementModel& model, const std::vector<BlockBinding>& bindings,
                          int error_state_size) {
  const auto& blocks = model.blocks();
  if (bindings.size() != blocks.size()) {
    throw std::invalid_argument(model.name() + ": " + std::to_string(bindings.size()) +
                                " bindings for " + std::to_string(blocks.size()) + " blocks");
  }
  std::vector<const double*> params;
  params.reserve(bindings.size());  // one allocation, not one per doubling
  for (const auto& b : bindings) params.push_back(b.value);
  MeasurementRows rows;
  std::vector<Eigen::MatrixXd> J;
  model.evaluate(params.data(), rows.residual, &J);
  rows.H = Eigen::MatrixXd::Zero(model.residualSize(), error_state_size);
  for (size_t k = 0; k < blocks.size(); ++k) {
    const int off = bindings[k].error_offset;
    if (off < 0) continue;
    if (off + blocks[k].tangentSize() > error_state_size) {
      throw std::out_of_range(model.name() + ": block " + blocks[k].key.str() +
                              " outside the state");
    }
    rows.H.middleCols(off, blocks[k].tangentSize()) += J[k];
  }
  rows.R = model.covariance();
  return rows;
}

}  // namespace giocal
