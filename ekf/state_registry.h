// StateRegistry: the EKF's error state as keyed variables that know their covariance index (the
// OpenVINS Type/StateHelper idea): add with a prior, remove (marginalize), condition on a value
// (the variable is then known), correct by box-plus, and bind to measurement models by StateKey.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <utility>
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
  /// Removes a variable, estimated (its rows and columns go: marginalization of a Gaussian) or
  /// known.
  void remove(const StateKey& key);
  /// Conditions the state on the variables' current values, as an exact measurement of each
  /// would: the others' covariance becomes P_rr - P_rk P_kk^-1 P_kr, and the variables leave the
  /// covariance and stay as known values that models bind as constants. A variable whose
  /// variance is not positive is taken out without conditioning. Vector variables of size 1 only.
  void condition(const std::vector<StateKey>& keys);
  /// Makes `copy` a stochastic clone of `key`: same value, fully correlated with it. An estimated
  /// `copy` that exists is overwritten where it stands (what removing it and cloning again
  /// gives, without resizing the covariance: the EKF re-clones every odometer interval).
  void clone(const StateKey& key, const StateKey& copy);

  /// True for an estimated or a known variable.
  bool has(const StateKey& key) const { return find(key) != nullptr; }
  bool isKnown(const StateKey& key) const { return has(key) && offset(key) < 0; }
  /// The variable's first column in the covariance; -1 for a known variable.
  int offset(const StateKey& key) const;
  const StateBlock& block(const StateKey& key) const;
  const Eigen::VectorXd& value(const StateKey& key) const;
  Eigen::VectorXd& value(const StateKey& key);
  std::vector<StateKey> keys() const { return order_; }  // estimated ones, in state order

  int dim() const { return static_cast<int>(P_.rows()); }
  const Eigen::MatrixXd& covariance() const { return P_; }
  Eigen::MatrixXd& covariance() { return P_; }
  Eigen::MatrixXd marginal(const StateKey& key) const;

  /// Applies an error-state correction: vectors add, rotations multiply on the right by Exp(d).
  void correct(const Eigen::VectorXd& dx);
  /// The values of `other` (the same variables), the covariance kept: an iterated update goes
  /// back to its prior's values without copying the whole registry.
  void setValues(const StateRegistry& other);
  /// The correction that takes `base` (same variables) to this state: this = base (+) dx, into
  /// `dx` (its storage reused).
  void minus(const StateRegistry& base, Eigen::VectorXd& dx) const;

  /// Bindings of a model's blocks to the variables `keys[k]` (throws for an unknown key); a known
  /// variable binds with error offset -1, so it enters the model as a constant.
  std::vector<BlockBinding> bind(const std::vector<StateKey>& keys) const;
  /// The same into `out`, reusing its storage.
  void bind(const std::vector<StateKey>& keys, std::vector<BlockBinding>& out) const;

 private:
  struct Variable {
    StateBlock block;
    Eigen::VectorXd value;
    int offset = 0;  // -1: known
  };
  /// Drops the rows and columns [off, off + m) of the covariance.
  void dropColumns(int off, int m);
  /// The variable of `key`, or null; `get` throws naming the key instead.
  const Variable* find(const StateKey& key) const;
  Variable& get(const StateKey& key);
  const Variable& get(const StateKey& key) const;
  // Sorted by key: a flat table (a tree cost an allocation per clone and a pointer chase per
  // look-up, and the models look variables up on every update).
  std::vector<std::pair<StateKey, Variable>> vars_;
  // vars_'s keys as StateKey::ordinal(), in the same order: what look-ups search (comparing
  // StateKeys field by field was 2 % of the paper run's instructions).
  std::vector<std::pair<std::uint64_t, std::uint64_t>> ordinals_;
  std::vector<StateKey> order_;
  Eigen::MatrixXd P_;
};

}  // namespace giocal
