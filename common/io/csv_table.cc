#include "common/io/csv_table.h"

#include <algorithm>
#include <charconv>
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

/// The comma-separated fields of `line`, trimmed (views into it: no copies per row).
void splitFields(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  size_t begin = 0;
  while (true) {
    const size_t comma = line.find(',', begin);
    out.push_back(
        trimView(line.substr(begin, comma == std::string_view::npos ? comma : comma - begin)));
    if (comma == std::string_view::npos) break;
    begin = comma + 1;
  }
}

/// A decimal number filling all of `f` (as strtod reads it, a leading '+' included); false if not.
/// std::from_chars: no locale, no allocation (reading a paper-preset log: 0.063 -> 0.027 s).
bool parseNumber(std::string_view f, double& v) {
  if (f.empty()) return false;
  const std::string_view digits = f[0] == '+' && f.size() > 1 && f[1] != '-' ? f.substr(1) : f;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (end != digits.data() + digits.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    v = std::strtod(std::string(f).c_str(), nullptr);  // strtod's overflow and underflow values
  } else if (ec != std::errc()) {
    return false;
  }
  return true;
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
  std::vector<std::string_view> fields;
  if (!nextFields(fields)) throw DataError(path, line_no_, "empty file, header missing");
  std::vector<std::string> names(fields.begin(), fields.end());
  if (names != header) {
    throw DataError(path, line_no_, "header must be '" + joinHeader(header) + "'");
  }
}

CsvRowReader::~CsvRowReader() = default;

bool CsvRowReader::nextFields(std::vector<std::string_view>& fields) {
  while (std::getline(in_->in, line_)) {
    ++line_no_;
    const std::string_view t = trimView(line_);
    if (t.empty() || t[0] == '#') continue;
    splitFields(t, fields);
    return true;
  }
  if (in_->in.bad()) throw DataError(path_, line_no_, "read error");
  return false;
}

CsvRowReader::RowKind CsvRowReader::readRow(std::vector<double>& row) {
  std::vector<std::string_view>& fields = fields_;
  if (!nextFields(fields)) return RowKind::kEnd;
  if (fields.size() != header_.size()) {
    // A last line cut short by an interrupted recording is damage; elsewhere it is structure.
    const size_t found = fields.size();
    std::vector<std::string_view> after;
    const long line = line_no_;
    if (fields.size() < header_.size() && !nextFields(after)) {
      ++damage_.cut_last_line;
      damage_.cut_line = line;
      return RowKind::kEnd;
    }
    throw DataError(path_, line,
                    "expected " + std::to_string(header_.size()) + " columns, found " +
                        std::to_string(found));  // (reading `after` replaced the line)
  }
  row.assign(fields.size(), 0.0);
  bool finite = true;
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string_view f = fields[i];
    double v = 0.0;
    if (!parseNumber(f, v)) {
      throw DataError(path_, line_no_,
                      "column '" + header_[i] + "' is not a number: '" + std::string(f) + "'");
    }
    if (!std::isfinite(v)) {
      if (i == 0) {
        throw DataError(path_, line_no_, "time is not finite: '" + std::string(f) + "'");
      }
      finite = false;
      continue;
    }
    if (i < ranges_.size() && (v < ranges_[i].min || v > ranges_[i].max)) {
      std::ostringstream msg;
      msg << "column '" << header_[i] << "' value " << v << " outside the physical range ["
          << ranges_[i].min << ", " << ranges_[i].max << "]";
      throw DataError(path_, line_no_, msg.str());
    }
    row[i] = v;
  }
  return finite ? RowKind::kRow : RowKind::kNonFinite;
}

void CsvRowReader::drop(long& count, long& first, long line) {
  if (count == 0) first = line;
  ++count;
  if (++bad_run_ > CsvDamage::kMaxBadRun) {
    throw DataError(path_, line_no_,
                    std::to_string(bad_run_) +
                        " rows in a row with NaN, a repeated time or time going backwards "
                        "(not a single damaged row: a broken log or a clock jump)");
  }
}

bool CsvRowReader::next(std::vector<double>& row) {
  // One row is held back until the next is read: a row whose time jumps far ahead of both
  // neighbours (one glitched stamp, a GPS week rollover) is told apart from the rows after it.
  while (true) {
    const RowKind kind = readRow(candidate_);
    if (kind == RowKind::kEnd) {
      if (!held_) return false;
      held_ = false;
      row.swap(held_row_);
      returned_line_ = held_line_;
      have_prev_ = true;
      prev_t_ = row[0];
      return true;
    }
    if (kind == RowKind::kNonFinite) {
      drop(damage_.non_finite, damage_.first_non_finite, line_no_);
      continue;
    }
    const double t = candidate_[0];
    const double ref = held_ ? held_row_[0] : prev_t_;
    const bool have_ref = held_ || have_prev_;
    if (have_ref && t == ref) {
      drop(damage_.duplicated, damage_.first_duplicated, line_no_);
      continue;
    }
    if (have_ref && t < ref) {
      // The held row far ahead of the row before it and of this one, which goes on from the row
      // before it: the held row is the odd one out. Otherwise this row went back in time.
      const bool held_jumped = held_ && have_prev_ && t > prev_t_ && ref - t > t - prev_t_;
      if (!held_jumped) {
        drop(damage_.out_of_order, damage_.first_out_of_order, line_no_);
        continue;
      }
      drop(damage_.jumped_ahead, damage_.first_jumped_ahead, held_line_);
      held_ = false;
    }
    bad_run_ = 0;
    const long line = line_no_;
    if (!held_) {
      held_row_.swap(candidate_);
      held_line_ = line;
      held_ = true;
      continue;
    }
    row.swap(held_row_);
    returned_line_ = held_line_;
    have_prev_ = true;
    prev_t_ = row[0];
    held_row_.swap(candidate_);
    held_line_ = line;
    return true;
  }
}

std::vector<std::string> CsvRowReader::warnings() const {
  std::vector<std::string> out;
  auto add = [&](long n, long first, const std::string& what) {
    if (n > 0) {
      out.push_back(path_ + ":" + std::to_string(first) + ": " + std::to_string(n) + " " + what +
                    " dropped (first here)");
    }
  };
  add(damage_.non_finite, damage_.first_non_finite, "rows with NaN or infinite values");
  add(damage_.duplicated, damage_.first_duplicated, "rows repeating the previous time");
  add(damage_.out_of_order, damage_.first_out_of_order, "rows with time going backwards");
  add(damage_.jumped_ahead, damage_.first_jumped_ahead,
      "rows stamped far ahead of the rows before and after them");
  add(damage_.cut_last_line, damage_.cut_line, "last line cut short");
  return out;
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
  table.warnings = reader.warnings();
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
