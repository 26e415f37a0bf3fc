// AmbiguityFixModel: integer fixes of double-differenced ambiguities as tight constraints on the
// single-differenced ambiguity states (the paper's r_AR): residual = (N_sat - N_ref) - fixed.
#pragma once

#include <string>
#include <vector>

#include "common/models/measurement_model.h"

namespace giocal {

struct DdAmbiguityFix {
  StateKey sat_block, ref_block;  // the SD ambiguity states [cycles]
  double value = 0.0;             // the integer DD ambiguity
};

class AmbiguityFixModel : public MeasurementModel {
 public:
  AmbiguityFixModel(std::vector<DdAmbiguityFix> fixes, double sigma_cycles);
  std::string name() const override { return "ambiguity_fix"; }
  /// One 1-D block per distinct SD ambiguity named in the fixes.
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return static_cast<int>(fixes_.size()); }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  std::vector<DdAmbiguityFix> fixes_;
  std::vector<std::pair<int, int>> index_;  // block of sat and ref per fix
  std::vector<StateBlock> blocks_;
  double sigma_;
};

}  // namespace giocal
