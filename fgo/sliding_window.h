// SlidingWindow: the factor graph's variables and factors, its Ceres solve, its linearization
// (Hessian and gradient over chosen variables, for covariances and ambiguity resolution), and
// marginalization of variables into a first-estimate linear prior (Schur complement).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/models/measurement_model.h"

namespace giocal {

/// A model bound to window variables: vars[k] is the variable for model block k.
struct Factor {
  std::shared_ptr<const MeasurementModel> model;
  std::vector<std::string> vars;
  double huber = 0.0;  // > 0: Huber loss with this threshold on the whitened residual
  std::string tag;     // what it is, for finding it again ("dd_phase#12", "fix", ...)
  // The model's whitener (its covariance is fixed): set when the factor enters a window.
  std::shared_ptr<const Eigen::MatrixXd> sqrt_info = nullptr;
};

class SlidingWindow {
 public:
  /// `block.name` is the variable's name; values are ambient ([w,x,y,z] for rotations).
  void addVariable(const StateBlock& block, const Eigen::VectorXd& value);
  void removeVariable(const std::string& name);  // and every factor on it
  bool has(const std::string& name) const { return vars_.count(name) != 0; }
  Eigen::VectorXd& value(const std::string& name);
  const Eigen::VectorXd& value(const std::string& name) const;
  const StateBlock& block(const std::string& name) const;
  /// Constant variables are not estimated (a lever arm given as known).
  void setConstant(const std::string& name, bool constant);
  /// Components of a vector variable held at their value (p_b_m.z in planar motion).
  void holdComponents(const std::string& name, const std::vector<int>& components);

  void addFactor(Factor f);
  /// Removes the factors whose tag equals `tag`; returns how many.
  int removeFactors(const std::string& tag);
  const std::vector<Factor>& factors() const { return factors_; }

  struct SolveReport {
    bool usable = false;
    int iterations = 0;
    double final_cost = 0.0;
  };
  /// Ceres' default relative cost-change tolerance is 1e-6.
  SolveReport solve(int max_iterations, double function_tolerance = 1e-6);

  /// Whitened Gauss-Newton system over `order` (tangent, in that order) from `factors` at the
  /// current values: H = sum J^T J, b = sum J^T r. Factors' other variables are ignored.
  void linearize(const std::vector<std::string>& order, const std::vector<const Factor*>& factors,
                 Eigen::MatrixXd& H, Eigen::VectorXd& b) const;
  /// The estimated variables that have factors, in a fixed order.
  std::vector<std::string> estimatedVariables() const;
  /// Marginal covariance (tangent) of `names` from the whole window's Hessian. The factorization
  /// is kept until the window changes: the covariances asked for at one state share it.
  Eigen::MatrixXd covariance(const std::vector<std::string>& names) const;

  /// Removes `names` and the factors on them, leaving one linear prior on their neighbours.
  void marginalize(const std::vector<std::string>& names);

 private:
  /// A factor's variable in the window's tangent (global) and in the factor's columns (local).
  struct Segment {
    int global, local, size;
  };
  /// Receives one factor's whitened J^T J over its window variables.
  using FactorVisitor =
      std::function<void(const std::vector<Segment>& segments, const Eigen::MatrixXd& Hf)>;
  /// Tangent offset of each of `order`'s variables; `size` gets the total.
  std::map<std::string, int> tangentOffsets(const std::vector<std::string>& order, int* size) const;
  /// Whitens and linearizes `factors` at the current values, handing each factor's J^T J to
  /// `visit` and adding J^T r into *b unless b is null; variables not in `offset` are ignored.
  void forEachWhitenedFactor(const std::map<std::string, int>& offset,
                             const std::vector<const Factor*>& factors, const FactorVisitor& visit,
                             Eigen::VectorXd* b) const;

  struct Variable {
    StateBlock block;
    Eigen::VectorXd value;
    bool constant = false;
    std::vector<int> held;
  };
  std::map<std::string, Variable> vars_;
  std::vector<Factor> factors_;
  long version_ = 0;  // bumped by every change of variables, values or factors
  struct HessianFactorization;
  mutable std::shared_ptr<const HessianFactorization> factorization_;
  const HessianFactorization& factorization() const;
};

}  // namespace giocal
