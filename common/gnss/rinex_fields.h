// Fixed-column field access for RINEX lines (columns are 1-based, as the format documents count).
#pragma once

#include <string>

namespace giocal::rinex {

/// Characters [col, col + width) of a line, blank-padded past its end.
std::string field(const std::string& line, int col, int width);
/// The header label, columns 61-80, trimmed.
std::string label(const std::string& line);
std::string trim(const std::string& s);

/// A Fortran-style number (D or E exponent). Blank gives `blank`; anything else that is not a
/// number returns false.
bool number(const std::string& text, double blank, double& out);

}  // namespace giocal::rinex
