// StateBlock: the name and kind of a state block a measurement model depends on.
#pragma once

#include <string>

namespace giocal {

/// Vector blocks perturb additively; Rotation blocks are Hamilton quaternions stored [w, x, y, z]
/// (4 values) and perturb on the right, q * Exp(dtheta) (3 tangent values).
enum class BlockKind { kVector, kRotation };

struct StateBlock {
  std::string name;  // e.g. "v_n_b"; two-state models suffix "@i" and "@j"
  BlockKind kind = BlockKind::kVector;
  int size = 3;  // tangent size; a Rotation has 3

  int ambientSize() const { return kind == BlockKind::kRotation ? 4 : size; }
  int tangentSize() const { return size; }
};

/// The block names every estimator in giocal uses.
namespace block {
inline const std::string kP = "p_n_b";
inline const std::string kV = "v_n_b";
inline const std::string kQ = "q_n_b";
inline const std::string kBa = "b_a";
inline const std::string kBg = "b_g";
inline const std::string kSv = "s_v";
inline const std::string kSw = "s_w";
inline const std::string kPbm = "p_b_m";
inline const std::string kQbm = "q_b_m";
inline const std::string kTdOdo = "t_d_odo";  // the odometer's delay against the IMU [s]
inline std::string at(const std::string& name, char epoch) { return name + "@" + epoch; }
}  // namespace block

inline StateBlock vectorBlock(const std::string& name, int size = 3) {
  return {name, BlockKind::kVector, size};
}
inline StateBlock rotationBlock(const std::string& name) { return {name, BlockKind::kRotation, 3}; }

}  // namespace giocal
