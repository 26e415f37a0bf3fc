#include "common/gnss/rinex_fields.h"

#include <cmath>
#include <cstdlib>

namespace giocal::rinex {

std::string field(const std::string& line, int col, int width) {
  const size_t start = static_cast<size_t>(col - 1);
  std::string out = start < line.size() ? line.substr(start, static_cast<size_t>(width)) : "";
  out.resize(static_cast<size_t>(width), ' ');
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string label(const std::string& line) { return trim(field(line, 61, 20)); }

bool number(const std::string& text, double blank, double& out) {
  std::string t = trim(text);
  if (t.empty()) {
    out = blank;
    return true;
  }
  for (char& c : t) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && std::isfinite(out);
}

}  // namespace giocal::rinex
