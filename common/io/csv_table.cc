#include "common/io/csv_table.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "common/io/atomic_file.h"
#include "common/io/data_error.h"
#include "common/io/text.h"

namespace giocal {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream ss(line);
  while (std::getline(ss, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::string joinHeader(const std::vector<std::string>& header) {
  std::string h;
  for (size_t i = 0; i < header.size(); ++i) h += (i ? "," : "") + header[i];
  return h;
}

}  // namespace

CsvTable readCsvTable(const std::string& path, const std::vector<std::string>& header,
                      const std::vector<ColumnRange>& ranges) {
  std::ifstream in(path);
  if (!in) throw DataError(path, 0, "cannot open file");
  CsvTable table;
  std::string line;
  long line_no = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = splitFields(t);
    if (!have_header) {
      std::vector<std::string> names;
      for (const auto& f : fields) names.push_back(trim(f));
      if (names != header) {
        throw DataError(path, line_no, "header must be '" + joinHeader(header) + "'");
      }
      have_header = true;
      continue;
    }
    if (fields.size() != header.size()) {
      throw DataError(path, line_no,
                      "expected " + std::to_string(header.size()) + " columns, found " +
                          std::to_string(fields.size()));
    }
    std::vector<double> row(fields.size());
    for (size_t i = 0; i < fields.size(); ++i) {
      const std::string f = trim(fields[i]);
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(f.c_str(), &end);
      if (f.empty() || end != f.c_str() + f.size()) {
        throw DataError(path, line_no, "column '" + header[i] + "' is not a number: '" + f + "'");
      }
      if (!std::isfinite(v)) {
        throw DataError(path, line_no, "column '" + header[i] + "' is not finite: '" + f + "'");
      }
      if (i < ranges.size() && (v < ranges[i].min || v > ranges[i].max)) {
        std::ostringstream msg;
        msg << "column '" << header[i] << "' value " << v << " outside the physical range ["
            << ranges[i].min << ", " << ranges[i].max << "]";
        throw DataError(path, line_no, msg.str());
      }
      row[i] = v;
    }
    if (!table.rows.empty()) {
      const double prev = table.rows.back()[0];
      if (row[0] == prev) throw DataError(path, line_no, "duplicated time " + fields[0]);
      if (row[0] < prev)
        throw DataError(path, line_no, "time goes backwards (" + trim(fields[0]) + ")");
    }
    table.rows.push_back(std::move(row));
    table.line_numbers.push_back(line_no);
  }
  if (in.bad()) throw DataError(path, line_no, "read error");
  if (!have_header) throw DataError(path, line_no, "empty file, header missing");
  return table;
}

void writeCsvTable(const std::string& path, const std::vector<std::string>& header,
                   const std::vector<std::vector<double>>& rows) {
  AtomicFile file(path);
  auto& out = file.stream();
  out << joinHeader(header) << '\n';
  out << std::setprecision(17);
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i];
    out << '\n';
  }
  file.commit();
}

}  // namespace giocal
