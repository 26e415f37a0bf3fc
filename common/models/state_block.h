// StateBlock: the key and kind of a state block a measurement model depends on.
#pragma once

#include "common/models/state_key.h"

namespace giocal {

/// Vector blocks perturb additively; Rotation blocks are Hamilton quaternions stored [w, x, y, z]
/// (4 values) and perturb on the right, q * Exp(dtheta) (3 tangent values).
enum class BlockKind { kVector, kRotation };

struct StateBlock {
  StateKey key;  // e.g. state::kV; two-state models use the copies Copy::kI and Copy::kJ
  BlockKind kind = BlockKind::kVector;
  int size = 3;  // tangent size; a Rotation has 3

  int ambientSize() const { return kind == BlockKind::kRotation ? 4 : size; }
  int tangentSize() const { return size; }
};

inline StateBlock vectorBlock(const StateKey& key, int size = 3) {
  return {key, BlockKind::kVector, size};
}
inline StateBlock rotationBlock(const StateKey& key) { return {key, BlockKind::kRotation, 3}; }

}  // namespace giocal
