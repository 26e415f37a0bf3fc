// Tags of the factor graph's factors: what a factor is and the epoch it belongs to ("imu#12"),
// for finding it again. The variables themselves are StateKeys (common/models/state_key.h).
#pragma once

#include <string>

namespace giocal::fgo_tag {

inline std::string tagged(const char* what, int k) {
  return std::string(what) + "#" + std::to_string(k);
}

}  // namespace giocal::fgo_tag
