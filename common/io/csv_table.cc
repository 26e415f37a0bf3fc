#include "common/io/csv_table.h"

#include <algorithm>
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

struct CsvRowReader::Stream {
  std::ifstream in;
};

CsvRowReader::CsvRowReader(const std::string& path, const std::vector<std::string>& header,
                           const std::vector<ColumnRange>& ranges)
    : in_(std::make_unique<Stream>()), path_(path), header_(header), ranges_(ranges) {
  in_->in.open(path);
  if (!in_->in) throw DataError(path, 0, "cannot open file");
  std::vector<std::string> fields;
  if (!nextFields(fields)) throw DataError(path, line_no_, "empty file, header missing");
  std::vector<std::string> names;
  for (const auto& f : fields) names.push_back(trim(f));
  if (names != header) {
    throw DataError(path, line_no_, "header must be '" + joinHeader(header) + "'");
  }
}

CsvRowReader::~CsvRowReader() = default;

bool CsvRowReader::nextFields(std::vector<std::string>& fields) {
  std::string line;
  while (std::getline(in_->in, line)) {
    ++line_no_;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    fields = splitFields(t);
    return true;
  }
  if (in_->in.bad()) throw DataError(path_, line_no_, "read error");
  return false;
}

bool CsvRowReader::next(std::vector<double>& row) {
  std::vector<std::string> fields;
  if (!nextFields(fields)) return false;
  if (fields.size() != header_.size()) {
    throw DataError(path_, line_no_,
                    "expected " + std::to_string(header_.size()) + " columns, found " +
                        std::to_string(fields.size()));
  }
  row.assign(fields.size(), 0.0);
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string f = trim(fields[i]);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(f.c_str(), &end);
    if (f.empty() || end != f.c_str() + f.size()) {
      throw DataError(path_, line_no_, "column '" + header_[i] + "' is not a number: '" + f + "'");
    }
    if (!std::isfinite(v)) {
      throw DataError(path_, line_no_, "column '" + header_[i] + "' is not finite: '" + f + "'");
    }
    if (i < ranges_.size() && (v < ranges_[i].min || v > ranges_[i].max)) {
      std::ostringstream msg;
      msg << "column '" << header_[i] << "' value " << v << " outside the physical range ["
          << ranges_[i].min << ", " << ranges_[i].max << "]";
      throw DataError(path_, line_no_, msg.str());
    }
    row[i] = v;
  }
  if (have_prev_) {
    if (row[0] == prev_t_) throw DataError(path_, line_no_, "duplicated time " + trim(fields[0]));
    if (row[0] < prev_t_)
      throw DataError(path_, line_no_, "time goes backwards (" + trim(fields[0]) + ")");
  }
  have_prev_ = true;
  prev_t_ = row[0];
  return true;
}

CsvTable readCsvTable(const std::string& path, const std::vector<std::string>& header,
                      const std::vector<ColumnRange>& ranges) {
  CsvRowReader reader(path, header, ranges);
  CsvTable table;
  std::vector<double> row;
  while (reader.next(row)) {
    table.rows.push_back(row);
    table.line_numbers.push_back(reader.line());
  }
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

namespace {
std::optional<double> leadingNumber(const std::string& line) {
  if (line.empty() || line[0] == '#') return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(line.c_str(), &end);
  if (end == line.c_str() || !std::isfinite(v)) return std::nullopt;
  return v;
}
}  // namespace

std::optional<std::pair<double, double>> csvTimeSpan(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string line;
  std::getline(in, line);  // header
  std::optional<double> first;
  while (!first && std::getline(in, line)) first = leadingNumber(line);
  if (!first) return std::nullopt;
  in.clear();
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(std::max<std::streamoff>(0, size - 4096));
  std::optional<double> last;
  std::getline(in, line);  // most likely a partial line
  while (std::getline(in, line)) {
    if (const std::optional<double> v = leadingNumber(line)) last = v;
  }
  if (!last || *last < *first) return std::nullopt;
  return std::make_pair(*first, *last);
}

}  // namespace giocal
