// Small text helpers shared by the file readers and the run messages.
#pragma once

#include <sstream>
#include <string>
#include <string_view>

namespace giocal {

/// s without leading and trailing blanks, tabs, CR and LF (a view into s, no copy).
inline std::string_view trimView(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

/// The same as a string.
inline std::string trim(const std::string& s) { return std::string(trimView(s)); }

/// A data time in a message: ten significant digits (GPS seconds to 0.1 s).
inline std::string timeText(double t) {
  std::ostringstream s;
  s.precision(10);
  s << t;
  return s.str();
}

/// v with `precision` digits after the point.
inline std::string fixedText(double v, int precision) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(precision);
  s << v;
  return s.str();
}

}  // namespace giocal
