// CsvTable: a numeric CSV file with a fixed header and a strictly increasing time column,
// checked row by row (column count, numbers, NaN/inf, time order, per-column ranges).
#pragma once

#include <string>
#include <vector>

namespace giocal {

/// Allowed range of one column; values outside it are rejected as physically impossible.
struct ColumnRange {
  double min = -1e300;
  double max = 1e300;
};

struct CsvTable {
  std::vector<std::vector<double>> rows;
  std::vector<long> line_numbers;  // line in the file of each row, for later messages
};

/// Reads `path`, whose first line must equal `header` (comma separated names, spaces ignored).
/// Column 0 is time, which must increase strictly. Blank lines and lines starting with '#' are
/// skipped. Throws DataError naming the file, the line and the problem.
CsvTable readCsvTable(const std::string& path, const std::vector<std::string>& header,
                      const std::vector<ColumnRange>& ranges);

/// Writes the header and rows atomically with enough digits to round-trip doubles.
void writeCsvTable(const std::string& path, const std::vector<std::string>& header,
                   const std::vector<std::vector<double>>& rows);

}  // namespace giocal
