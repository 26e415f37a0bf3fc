#include "common/models/measurement_rows.h"

#include <stdexcept>

namespace giocal {

MeasurementRows linearize(const MeasurementModel& model, const std::vector<BlockBinding>& bindings,
                          int error_state_size) {
  MeasurementRows rows;
  LinearizeScratch scratch;
  linearize(model, bindings, error_state_size, rows, scratch);
  return rows;
}

void linearize(const MeasurementModel& model, const std::vector<BlockBinding>& bindings,
               int error_state_size, MeasurementRows& rows, LinearizeScratch& scratch) {
  const auto& blocks = model.blocks();
  if (bindings.size() != blocks.size()) {
    throw std::invalid_argument(model.name() + ": " + std::to_string(bindings.size()) +
                                " bindings for " + std::to_string(blocks.size()) + " blocks");
  }
  scratch.params.clear();
  for (const auto& b : bindings) scratch.params.push_back(b.value);
  model.evaluate(scratch.params.data(), rows.residual, &scratch.J);
  rows.H.setZero(model.residualSize(), error_state_size);
  for (size_t k = 0; k < blocks.size(); ++k) {
    const int off = bindings[k].error_offset;
    if (off < 0) continue;
    if (off + blocks[k].tangentSize() > error_state_size) {
      throw std::out_of_range(model.name() + ": block " + blocks[k].key.str() +
                              " outside the state");
    }
    rows.H.middleCols(off, blocks[k].tangentSize()) += scratch.J[k];
  }
  model.covarianceInto(rows.R);
}

}  // namespace giocal
