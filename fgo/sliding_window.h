// SlidingWindow: the factor graph's variables and factors, their least-squares solve (giocal's own
// Gauss-Newton on the sparse Hessian, or Ceres), covariances from the solve's last factorization,
// and marginalization of variables into a first-estimate linear prior (Schur complement).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/models/measurement_model.h"
#include "common/models/state_key.h"
#include "options/fgo_options.h"

namespace giocal {

/// A model bound to window variables: vars[k] is the variable for model block k.
struct Factor {
  std::shared_ptr<const MeasurementModel> model;
  std::vector<StateKey> vars;
  double huber = 0.0;  // > 0: Huber loss with this threshold on the whitened residual
  std::string tag;     // what it is, for finding it again ("dd_phase#12", "fix", ...)
  // The model's whitener (its covariance is fixed): set when the factor enters a window, with its
  // shape, which decides how it is applied (whitener() gives a lower-triangular one).
  std::shared_ptr<const Eigen::MatrixXd> sqrt_info = nullptr;
  enum class Shape { kDense, kLower, kDiagonal } sqrt_info_shape = Shape::kDense;
  // A lower-triangular whitener's diagonal blocks (first row, rows): independent groups of rows,
  // as the DD factor's code and phase per reference satellite and band, are whitened apart.
  std::vector<std::pair<int, int>> sqrt_info_blocks = {};
};

class SlidingWindow {
 public:
  void setSolver(WindowSolver solver) { solver_ = solver; }
  /// Gauss-Newton also ends when what is left to gain would move the window by at most `sigma` in
  /// its own posterior metric (a predicted or actual cost change below sigma^2 / 2), so that no
  /// state moves by more than `sigma` of its own sigma. 0 (the default): the relative tolerance
  /// alone, as Ceres.
  void setStepTolerance(double sigma) { step_sigma_ = sigma; }
  /// `block.key` is the variable; values are ambient ([w,x,y,z] for rotations).
  void addVariable(const StateBlock& block, const Eigen::VectorXd& value);
  void removeVariable(const StateKey& name);  // and every factor on it
  bool has(const StateKey& name) const { return vars_.count(name) != 0; }
  Eigen::VectorXd& value(const StateKey& name);
  const Eigen::VectorXd& value(const StateKey& name) const;
  const StateBlock& block(const StateKey& name) const;
  /// Constant variables are not estimated (a lever arm given as known).
  void setConstant(const StateKey& name, bool constant);
  bool isConstant(const StateKey& name) const { return vars_.at(name).constant; }
  /// Components of a vector variable held at their value (p_b_m.z in planar motion).
  void holdComponents(const StateKey& name, const std::vector<int>& components);

  void addFactor(Factor f);
  /// Removes the factors whose tag equals `tag`; returns how many.
  int removeFactors(const std::string& tag);
  const std::vector<Factor>& factors() const { return factors_; }

  struct SolveReport {
    bool usable = false;
    int iterations = 0;
    double final_cost = 0.0;
    // Why the solve ended short of converging, when it failed numerically: "non-finite cost",
    // "non-finite step", "damping exhausted", or Ceres' message; empty otherwise.
    std::string failure;
  };
  /// Stops when a step changes the cost by less than `function_tolerance` of it (Ceres' default,
  /// 1e-6), when the own solver's next step is predicted to gain less than that (asked first of
  /// the last step's factorization, then of a new one), when the step is below 1e-8 relative, or
  /// after `max_iterations` steps.
  SolveReport solve(int max_iterations, double function_tolerance = 1e-6);

  /// Whitened Gauss-Newton system over `order` (tangent, in that order) from `factors` at the
  /// current values: H = sum J^T J, b = sum J^T r, with the solve's robust (Huber) weights.
  /// Factors' other variables are ignored.
  void linearize(const std::vector<StateKey>& order, const std::vector<const Factor*>& factors,
                 Eigen::MatrixXd& H, Eigen::VectorXd& b) const;
  /// The estimated variables that have factors, in a fixed order.
  std::vector<StateKey> estimatedVariables() const;
  /// Marginal covariance (tangent) of `names` from the whole window's robust Hessian (held
  /// components keep their factors' information). The factorization is kept until the window
  /// changes: the covariances asked for at one state, and after a Gauss-Newton solve, share it.
  Eigen::MatrixXd covariance(const std::vector<StateKey>& names) const;
  /// G^T C G with C = covariance(names): one triangular solve with G's columns, cheaper than C
  /// when G has fewer columns than `names` have tangent dimensions.
  Eigen::MatrixXd covarianceAlong(const std::vector<StateKey>& names,
                                  const Eigen::MatrixXd& G) const;

  /// Removes `names` and the factors on them, leaving one linear prior on their neighbours.
  void marginalize(const std::vector<StateKey>& names);

  /// How many sparsity patterns were analysed (ordering, symbolic factor): a window that slid
  /// into the shape of the last reuses its analysis.
  long symbolicAnalyses() const { return symbolic_analyses_; }

 private:
  /// A factor's variable in the window's tangent (global) and in the factor's columns (local).
  struct Segment {
    int global, local, size;
  };
  struct Variable {
    StateBlock block;
    Eigen::VectorXd value;
    bool constant = false;
    std::vector<int> held;
  };
  /// One factor's place in a linearization: its variables, and the columns of those in the
  /// linearization's order (`blocks`: their model block indices).
  struct FactorLayout {
    const Factor* factor = nullptr;
    std::vector<const Variable*> vars;
    std::vector<Segment> segments;
    std::vector<size_t> blocks;
    int cols = 0;
  };
  /// Receives factor k's whitened J^T J over its window variables (its lower triangle only).
  using FactorVisitor =
      std::function<void(size_t k, const FactorLayout& layout, const Eigen::MatrixXd& Hf)>;
  /// Tangent offset of each of `order`'s variables; `size` gets the total.
  std::map<StateKey, int> tangentOffsets(const std::vector<StateKey>& order, int* size) const;
  /// The layouts of `factors` over the variables in `offset` (others are left out); factors with
  /// none of them are skipped.
  std::vector<FactorLayout> layouts(const std::map<StateKey, int>& offset,
                                    const std::vector<const Factor*>& factors) const;
  /// Whitens and linearizes the factors at the current values, handing each factor's J^T J to
  /// `visit` and adding J^T r into *b unless b is null.
  /// `robust`: Huber factors beyond their threshold are down-weighted by sqrt(rho') (as Ceres
  /// does for a loss with rho'' <= 0), and *cost (unless null) gets sum rho(|r|^2) / 2.
  void forEachWhitenedFactor(const std::vector<FactorLayout>& factors, const FactorVisitor& visit,
                             Eigen::VectorXd* b, bool robust = false, double* cost = nullptr) const;
  SolveReport solveWithCeres(int max_iterations, double function_tolerance);
  /// G^T C G of the tangent of `names` (G null: C).
  Eigen::MatrixXd marginalOf(const std::vector<StateKey>& names, const Eigen::MatrixXd* G) const;
  SolveReport solveGaussNewton(int max_iterations, double function_tolerance);

  std::map<StateKey, Variable> vars_;
  std::vector<Factor> factors_;
  long version_ = 0;    // bumped by every change of variables, values or factors
  long structure_ = 0;  // bumped by every change of variables or factors (not of values)
  WindowSolver solver_ = WindowSolver::kGaussNewton;
  double step_sigma_ = 0.0;
  /// The robust Hessian, gradient and cost of the whole window at one version of it, factorized
  /// on first use.
  struct Linearization;
  /// One window structure's plan, shared by its linearizations: variable offsets, factor
  /// layouts, H's pattern and where each factor's entries go, CHOLMOD's ordering and symbolic
  /// factor (and the numeric factor of the linearization last factorized).
  struct WindowPlan;
  std::shared_ptr<WindowPlan> plan() const;  // of the current structure
  std::shared_ptr<Linearization> linearizeWindow() const;
  mutable std::shared_ptr<Linearization> linearization_;
  mutable std::shared_ptr<WindowPlan> plan_;
  mutable long linearizations_ = 0;
  mutable long symbolic_analyses_ = 0;
  /// The current version's linearization, factorized.
  Linearization& factorization() const;
};

}  // namespace giocal
