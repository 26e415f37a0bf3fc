// CsvTable: a numeric CSV file with a fixed header and a strictly increasing time column,
// checked row by row (column count, numbers, NaN/inf, time order, per-column ranges).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace giocal {

/// Allowed range of one column; values outside it are rejected as physically impossible.
struct ColumnRange {
  double min = -1e300;
  double max = 1e300;
};

struct CsvTable {
  std::vector<std::vector<double>> rows;
  std::vector<long> line_numbers;     // line in the file of each row, for later messages
  std::vector<std::string> warnings;  // recoverable damage dropped (CsvRowReader::warnings)
};

/// Rows a reader dropped as recoverable damage: a row with NaN or infinite values (up to
/// kMaxBadRun in a row), a repeated time, a single time out of order, a single time far ahead of
/// the rows around it, a cut last line. Anything longer or elsewhere is structural and stops the
/// read.
struct CsvDamage {
  static constexpr int kMaxBadRun = 100;
  long non_finite = 0, duplicated = 0, out_of_order = 0, jumped_ahead = 0, cut_last_line = 0;
  long first_non_finite = 0, first_duplicated = 0, first_out_of_order = 0, first_jumped_ahead = 0,
       cut_line = 0;
};

/// Reads a CsvTable row by row (constant memory): the same checks as readCsvTable().
class CsvRowReader {
 public:
  /// Opens `path` and checks its header; throws DataError naming the file, line and problem.
  CsvRowReader(const std::string& path, const std::vector<std::string>& header,
               const std::vector<ColumnRange>& ranges);
  ~CsvRowReader();
  CsvRowReader(const CsvRowReader&) = delete;
  CsvRowReader& operator=(const CsvRowReader&) = delete;
  /// The next row; false at the end of the file. Throws DataError on a bad row.
  bool next(std::vector<double>& row);
  long line() const { return returned_line_; }  // of the row last returned
  const std::string& path() const { return path_; }
  const CsvDamage& damage() const { return damage_; }
  /// One line per kind of damage dropped so far, naming the file and the first line.
  std::vector<std::string> warnings() const;

 private:
  /// The next non-blank, non-comment line's trimmed fields, as views into line_.
  bool nextFields(std::vector<std::string_view>& fields);
  enum class RowKind { kEnd, kRow, kNonFinite };
  /// The next row, its columns and ranges checked (not its time order).
  RowKind readRow(std::vector<double>& row);
  /// Counts a dropped row; too many in a row stop the read.
  void drop(long& count, long& first, long line);
  struct Stream;
  std::unique_ptr<Stream> in_;
  std::string path_;
  std::vector<std::string> header_;
  std::vector<ColumnRange> ranges_;
  long line_no_ = 0;
  bool have_prev_ = false;
  double prev_t_ = 0.0;
  CsvDamage damage_;
  int bad_run_ = 0;    // consecutive rows dropped
  bool held_ = false;  // a row read but not returned yet (held_row_)
  std::vector<double> held_row_, candidate_;
  long held_line_ = 0, returned_line_ = 0;
  std::string line_;                      // the line last read
  std::vector<std::string_view> fields_;  // its fields (kept: no allocation per row)
};

/// Reads `path`, whose first line must equal `header` (comma separated names, spaces ignored).
/// Column 0 is time, which must increase strictly. Blank lines and lines starting with '#' are
/// skipped; recoverable damage is dropped (CsvDamage) and listed in `warnings`. Throws DataError
/// naming the file, the line and the problem.
CsvTable readCsvTable(const std::string& path, const std::vector<std::string>& header,
                      const std::vector<ColumnRange>& ranges);

/// The times of the first and the last row of a CSV file whose first column is time, read from its
/// beginning and its end only (for progress reports); nullopt when they cannot be read.
std::optional<std::pair<double, double>> csvTimeSpan(const std::string& path);

/// Writes the header and rows atomically with enough digits to round-trip doubles.
void writeCsvTable(const std::string& path, const std::vector<std::string>& header,
                   const std::vector<std::vector<double>>& rows);

}  // namespace giocal
