// Names of the factor graph's variables: the calibration blocks, and per-epoch names tagged with
// the epoch's number ("p_n_b#12").
#pragma once

#include <string>

namespace giocal::fgo_var {

constexpr const char* kPbm = "p_b_m";
constexpr const char* kQbm = "q_b_m";
constexpr const char* kPbg = "p_b_g";

inline std::string tagged(const char* what, int k) {
  return std::string(what) + "#" + std::to_string(k);
}

}  // namespace giocal::fgo_var
