// StateRegistry: the EKF's error state as keyed variables that know their covariance index (the
// OpenVINS Type/StateHelper idea): add with a prior, remove (marginalize), correct by box-plus,
// and bind to measurement models by StateKey.
#pragma once

#include <Eigen/Core>
#include <map>
#include <vector>

#include "common/models/measurement_rows.h"
#include "common/models/state_block.h"

namespace giocal {

class StateRegistry {
 public:
  /// Adds a variable at the end of the state with its value (ambient: [w,x,y,z] for rotations)
  /// and its covariance (tangent), uncorrelated with the rest. Throws if the key exists.
  void add(const StateBlock& block, const Eigen::VectorXd& value,
           const Eigen::MatrixXd& covariance);
  /// Removes a variable and its rows and columns (marginalization of a Gaussian).
  void remove(const StateKey& key);
  /// Adds `copy` as a stochastic clone of `key`: same value, fully correlated with it.
  void clone(const StateKey& key, const StateKey& copy);

  bool has(const StateKey& key) const { return vars_.count(key) != 0; }
  int offset(const StateKey& key) const;
  const StateBlock& block(const StateKey& key) const;
  const Eigen::VectorXd& value(const StateKey& key) const;
  Eigen::VectorXd& value(const StateKey& key);
  std::vector<StateKey> keys() const { return order_; }  // in state order

  int dim() const { return static_cast<int>(P_.rows()); }
  const Eigen::MatrixXd& covariance() const { return P_; }
  Eigen::MatrixXd& covariance() { return P_; }
  Eigen::MatrixXd marginal(const StateKey& key) const;

  /// Applies an error-state correction: vectors add, rotations multiply on the right by Exp(d).
  void correct(const Eigen::VectorXd& dx);
  /// The values of `other` (the same variables), the covariance kept: an iterated update goes
  /// back to its prior's values without copying the whole registry.
  void setValues(const StateRegistry& other);
  /// The correction that takes `base` (same variables) to this state: this = base (+) dx.
  Eigen::VectorXd minus(const StateRegistry& base) const;

  /// Bindings of a model's blocks to the variables `keys[k]` (throws for an unknown key).
  std::vector<BlockBinding> bind(const std::vector<StateKey>& keys) const;

 private:
  struct Variable {
    StateBlock block;
    Eigen::VectorXd value;
    int offset = 0;
  };
  std::map<StateKey, Variable> vars_;
  std::vector<StateKey> order_;
  Eigen::MatrixXd P_;
};

}  // namespace giocal
