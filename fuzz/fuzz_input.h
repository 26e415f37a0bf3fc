// FuzzInput: a fuzzer's bytes as a file (giocal's readers take paths), in a folder of its own per
// process under /dev/shm when it exists; and the rule every harness checks: bad input may throw a
// std::exception with a message, nothing else (no crash, no hang, no sanitizer report).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace giocal::fuzz {

inline std::string folder() {
  static const std::string dir = [] {
    const std::filesystem::path base =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    const std::filesystem::path d = base / ("giocal_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

/// Writes the input to <folder>/<name> and returns its path.
inline std::string asFile(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = folder() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// Runs `read`; a std::exception is the reader saying no, which is fine.
template <class F>
void expectNoCrash(F read) {
  try {
    read();
  } catch (const std::exception&) {
  }
}

}  // namespace giocal::fuzz
