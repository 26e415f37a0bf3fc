#include "common/gnss/rinex_fields.h"

#include <cmath>
#include <cstdlib>

#include "common/io/text.h"

namespace giocal::rinex {

std::string field(const std::string& line, int col, int width) {
  const size_t start = static_cast<size_t>(col - 1);
  std::string out = start < line.size() ? line.substr(start, static_cast<size_t>(width)) : "";
  out.resize(static_cast<size_t>(width), ' ');
  return out;
}

std::string trim(const std::string& s) { return giocal::trim(s); }

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

std::string headerLine(const std::string& content, const std::string& label) {
  std::string line = content;
  line.resize(60, ' ');
  return line + label + "\n";
}

bool integer(double v, int min, int max, int& out) {
  if (!std::isfinite(v) || v < min || v > max || v != std::floor(v)) return false;
  out = static_cast<int>(v);
  return true;
}

}  // namespace giocal::rinex
