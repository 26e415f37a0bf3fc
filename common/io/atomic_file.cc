#include "common/io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "common/io/output_set.h"

namespace giocal {

AtomicFile::AtomicFile(const std::string& path)
    : path_(path), tmp_path_(path + ".giocal-tmp." + std::to_string(::getpid())) {
  const std::filesystem::path p(path);
  sweepStaleTemporaries(p.has_parent_path() ? p.parent_path().string() : ".",
                        p.filename().string());
  out_.open(tmp_path_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error(path_ + ": cannot open for writing");
  out_.precision(12);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_path_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error(path_ + ": write failed");
  out_.close();
  if (std::rename(tmp_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(path_ + ": cannot rename temporary file into place: " +
                             std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace giocal
