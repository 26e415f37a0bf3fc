// Fixed-column field access for RINEX lines (columns are 1-based, as the format documents count).
#pragma once

#include <string>

namespace giocal::rinex {

/// Characters [col, col + width) of a line, blank-padded past its end.
std::string field(const std::string& line, int col, int width);
/// The header label, columns 61-80, trimmed.
std::string label(const std::string& line);
std::string trim(const std::string& s);
/// A header line as the writers make it: content in columns 1-60, the label from column 61.
std::string headerLine(const std::string& content, const std::string& label);

/// A Fortran-style number (D or E exponent). Blank gives `blank`; anything else that is not a
/// number returns false.
bool number(const std::string& text, double blank, double& out);

/// v as an int when it is finite, a whole number and within [min, max]; false otherwise (a file
/// value such as 2e24 must never reach an int conversion).
bool integer(double v, int min, int max, int& out);

}  // namespace giocal::rinex
