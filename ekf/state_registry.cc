#include "ekf/state_registry.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "common/math/rotation.h"
#include "common/math/sorted_by_key.h"

namespace giocal {

void StateRegistry::add(const StateBlock& block, const Eigen::VectorXd& value,
                        const Eigen::MatrixXd& covariance) {
  if (has(block.key)) {
    throw std::invalid_argument("state variable '" + block.key.str() + "' exists");
  }
  if (value.size() != block.ambientSize() || covariance.rows() != block.tangentSize() ||
      covariance.cols() != block.tangentSize()) {
    throw std::invalid_argument("state variable '" + block.key.str() +
                                "': value or covariance size");
  }
  const int n = dim(), m = block.tangentSize();
  P_.conservativeResize(n + m, n + m);
  P_.bottomRows(m).setZero();
  P_.rightCols(m).setZero();
  P_.bottomRightCorner(m, m) = covariance;
  const auto at = lowerBoundKey(vars_, block.key);
  ordinals_.insert(ordinals_.begin() + (at - vars_.begin()), block.key.ordinal());
  vars_.insert(at, {block.key, Variable{block, value, n}});
  order_.push_back(block.key);
}

void StateRegistry::remove(const StateKey& key) {
  const int off = offset(key);
  if (off >= 0) dropColumns(off, block(key).tangentSize());
  const auto at = findKey(vars_, key);
  ordinals_.erase(ordinals_.begin() + (at - vars_.begin()));
  vars_.erase(at);
  if (off >= 0) order_.erase(std::find(order_.begin(), order_.end(), key));
}

void StateRegistry::dropColumns(int off, int m) {
  const int n = dim();
  Eigen::MatrixXd P(n - m, n - m);
  const int tail = n - off - m;
  P.topLeftCorner(off, off) = P_.topLeftCorner(off, off);
  P.topRightCorner(off, tail) = P_.topRightCorner(off, tail);
  P.bottomLeftCorner(tail, off) = P_.bottomLeftCorner(tail, off);
  P.bottomRightCorner(tail, tail) = P_.bottomRightCorner(tail, tail);
  P_ = P;
  for (auto& [k, v] : vars_) {
    if (v.offset > off) v.offset -= m;
  }
}

void StateRegistry::condition(const std::vector<StateKey>& keys) {
  for (const StateKey& key : keys) {
    const int off = offset(key);
    if (off < 0) continue;
    if (block(key).kind != BlockKind::kVector || block(key).size != 1) {
      throw std::invalid_argument("state variable '" + key.str() +
                                  "': only scalars are conditioned");
    }
    // One exact scalar measurement at a time: the sequence equals the joint conditioning.
    const double pkk = P_(off, off);
    if (pkk > 0.0) {
      const Eigen::VectorXd p = P_.col(off);
      P_.noalias() -= (p / pkk) * p.transpose();
    }
    dropColumns(off, 1);
    get(key).offset = -1;
    order_.erase(std::find(order_.begin(), order_.end(), key));
  }
}

void StateRegistry::clone(const StateKey& key, const StateKey& copy) {
  StateBlock b = block(key);
  const int src = offset(key), m = b.tangentSize();
  Variable* existing = has(copy) ? &get(copy) : nullptr;
  if (existing &&
      (existing->offset < 0 || existing->block.kind != b.kind || existing->block.size != b.size)) {
    remove(copy);  // known, or another shape: cloned anew at the end
    existing = nullptr;
  }
  if (existing) {
    existing->value = value(key);  // same size: no allocation
  } else {
    b.key = copy;
    add(b, value(key), marginal(key));
  }
  const int dst = offset(copy);
  P_.block(dst, 0, m, dim()) = P_.block(src, 0, m, dim());
  P_.block(0, dst, dim(), m) = P_.block(0, src, dim(), m);
  P_.block(dst, dst, m, m) = P_.block(src, src, m, m);
}

const StateRegistry::Variable* StateRegistry::find(const StateKey& key) const {
  const auto ordinal = key.ordinal();
  const auto it = std::lower_bound(ordinals_.begin(), ordinals_.end(), ordinal);
  if (it == ordinals_.end() || *it != ordinal) return nullptr;
  return &vars_[static_cast<size_t>(it - ordinals_.begin())].second;
}

const StateRegistry::Variable& StateRegistry::get(const StateKey& key) const {
  const Variable* v = find(key);
  if (!v) throw std::out_of_range("no state variable '" + key.str() + "'");
  return *v;
}

StateRegistry::Variable& StateRegistry::get(const StateKey& key) {
  return const_cast<Variable&>(std::as_const(*this).get(key));
}

int StateRegistry::offset(const StateKey& key) const { return get(key).offset; }

const StateBlock& StateRegistry::block(const StateKey& key) const { return get(key).block; }

const Eigen::VectorXd& StateRegistry::value(const StateKey& key) const { return get(key).value; }

Eigen::VectorXd& StateRegistry::value(const StateKey& key) { return get(key).value; }

Eigen::MatrixXd StateRegistry::marginal(const StateKey& key) const {
  const int m = block(key).tangentSize(), off = offset(key);
  if (off < 0) throw std::invalid_argument("state variable '" + key.str() + "' is known");
  return P_.block(off, off, m, m);
}

void StateRegistry::correct(const Eigen::VectorXd& dx) {
  if (dx.size() != dim()) throw std::invalid_argument("correction size differs from the state");
  for (auto& [key, v] : vars_) {
    if (v.offset < 0) continue;
    if (v.block.kind == BlockKind::kRotation) {
      const Quat q = boxPlus(quatFromWxyz(v.value.data()), dx.segment<3>(v.offset));
      quatToWxyz(q, v.value.data());
    } else {
      v.value += dx.segment(v.offset, v.block.size);
    }
  }
}

void StateRegistry::setValues(const StateRegistry& other) {
  if (other.order_ != order_ || other.vars_.size() != vars_.size())
    throw std::invalid_argument("StateRegistry: different variables");
  auto from = other.vars_.begin();
  for (auto& entry : vars_) (entry.second.value = (from++)->second.value);
}

void StateRegistry::minus(const StateRegistry& base, Eigen::VectorXd& dx) const {
  dx.resize(dim());
  for (const auto& [key, v] : vars_) {
    if (v.offset < 0) continue;
    const Eigen::VectorXd& b = base.value(key);
    if (v.block.kind == BlockKind::kRotation) {
      dx.segment<3>(v.offset) = boxMinus(quatFromWxyz(v.value.data()), quatFromWxyz(b.data()));
    } else {
      dx.segment(v.offset, v.block.size) = v.value - b;
    }
  }
}

std::vector<BlockBinding> StateRegistry::bind(const std::vector<StateKey>& keys) const {
  std::vector<BlockBinding> out;
  out.reserve(keys.size());
  bind(keys, out);
  return out;
}

void StateRegistry::bind(const std::vector<StateKey>& keys, std::vector<BlockBinding>& out) const {
  out.clear();
  for (const StateKey& k : keys) {
    const Variable* v = find(k);
    if (!v) throw std::out_of_range("no state variable '" + k.str() + "' to bind");
    out.push_back({v->value.data(), v->offset});
  }
}

}  // namespace giocal
