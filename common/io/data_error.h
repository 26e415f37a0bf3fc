// DataError: bad input, reported as one line "file:line: problem".
#pragma once

#include <stdexcept>
#include <string>

namespace giocal {

class DataError : public std::runtime_error {
 public:
  DataError(const std::string& file, long line, const std::string& problem)
      : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                           problem),
        file_(file),
        line_(line) {}
  const std::string& file() const { return file_; }
  long line() const { return line_; }

 private:
  std::string file_;
  long line_;
};

}  // namespace giocal
