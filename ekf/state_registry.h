// StateRegistry: the EKF's error state as named variables that know their covariance index (the
// OpenVINS Type/StateHelper idea): add with a prior, remove (marginalize), correct by box-plus,
// and bind to measurement models by name.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "common/models/measurement_rows.h"
#include "common/models/state_block.h"

namespace giocal {

class StateRegistry {
 public:
  /// Adds a variable at the end of the state with its value (ambient: [w,x,y,z] for rotations)
  /// and its covariance (tangent), uncorrelated with the rest. Throws if the name exists.
  void add(const StateBlock& block, const Eigen::VectorXd& value,
           const Eigen::MatrixXd& covariance);
  /// Removes a variable and its rows and columns (marginalization of a Gaussian).
  void remove(const std::string& name);
  /// Adds `copy` as a stochastic clone of `name`: same value, fully correlated with it.
  void clone(const std::string& name, const std::string& copy);

  bool has(const std::string& name) const { return vars_.count(name) != 0; }
  int offset(const std::string& name) const;
  const StateBlock& block(const std::string& name) const;
  const Eigen::VectorXd& value(const std::string& name) const;
  Eigen::VectorXd& value(const std::string& name);
  std::vector<std::string> names() const;  // in state order

  int dim() const { return static_cast<int>(P_.rows()); }
  const Eigen::MatrixXd& covariance() const { return P_; }
  Eigen::MatrixXd& covariance() { return P_; }
  Eigen::MatrixXd marginal(const std::string& name) const;

  /// Applies an error-state correction: vectors add, rotations multiply on the right by Exp(d).
  void correct(const Eigen::VectorXd& dx);
  /// The values of `other` (the same variables), the covariance kept: an iterated update goes
  /// back to its prior's values without copying the whole registry.
  void setValues(const StateRegistry& other);
  /// The correction that takes `base` (same variables) to this state: this = base (+) dx.
  Eigen::VectorXd minus(const StateRegistry& base) const;

  /// Bindings of a model's blocks to the variables `names[k]` (throws for an unknown name).
  std::vector<BlockBinding> bind(const std::vector<std::string>& names) const;

 private:
  struct Variable {
    StateBlock block;
    Eigen::VectorXd value;
    int offset = 0;
  };
  std::map<std::string, Variable> vars_;
  std::vector<std::string> order_;
  Eigen::MatrixXd P_;
};

}  // namespace giocal
