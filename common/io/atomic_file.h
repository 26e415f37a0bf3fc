// AtomicFile: writes to "<path>.giocal-tmp.<pid>" and renames onto <path> on commit, so an
// interrupted run never leaves a half-written file (a killed one's temporary is swept next time).
#pragma once

#include <fstream>
#include <string>

namespace giocal {

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();  // removes the temporary file if commit() was never reached
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes, checks for write errors and renames onto the final path; throws on failure.
  void commit();

 private:
  std::string path_;
  std::string tmp_path_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace giocal
