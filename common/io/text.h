// Small text helpers shared by the file readers.
#pragma once

#include <string>

namespace giocal {

/// s without leading and trailing blanks, tabs, CR and LF.
inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

}  // namespace giocal
