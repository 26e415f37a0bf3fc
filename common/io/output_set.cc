#include "common/io/output_set.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "common/io/data_error.h"

namespace fs = std::filesystem;

namespace giocal {
namespace {

constexpr const char* kStagingPrefix = ".giocal-partial.";

constexpr const char* kTemporaryInfix = ".giocal-tmp.";

/// The pid a temporary's name ends with (".giocal-partial.<pid>", "<file>.giocal-tmp.<pid>"), or 0.
long pidOfTemporary(const std::string& name) {
  std::string digits;
  if (name.rfind(kStagingPrefix, 0) == 0) {
    digits = name.substr(std::string(kStagingPrefix).size());
  } else {
    const size_t at = name.rfind(kTemporaryInfix);
    if (at == std::string::npos) return 0;
    digits = name.substr(at + std::string(kTemporaryInfix).size());
  }
  if (digits.empty() || digits.size() > 9 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return std::stol(digits);
}

bool processIsRunning(long pid) {
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

}  // namespace

void sweepStaleTemporaries(const std::string& folder, const std::string& of_file) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (!of_file.empty() && name.rfind(of_file + kTemporaryInfix, 0) != 0) continue;
    const long pid = pidOfTemporary(name);
    if (pid <= 0 || pid == ::getpid() || processIsRunning(pid)) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

OutputSet::OutputSet(std::string folder) : folder_(std::move(folder)) {
  fs::create_directories(folder_);
  sweepStaleTemporaries(folder_);
  staging_ = folder_ + "/" + kStagingPrefix + std::to_string(::getpid());
  fs::remove_all(staging_);
  fs::create_directory(staging_);
}

OutputSet::~OutputSet() {
  if (committed_) return;
  files_.clear();  // closes the streams before their files go
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

std::string OutputSet::stagedPath(const std::string& name, bool marker) {
  if (name.empty() || fs::path(name).is_absolute() || name.find("..") != std::string::npos) {
    throw std::invalid_argument("output name '" + name + "' is not a plain relative path");
  }
  File& f = files_[name];
  f.marker = f.marker || marker;
  const fs::path p = fs::path(staging_) / name;
  fs::create_directories(p.parent_path());
  return p.string();
}

std::ostream& OutputSet::open(const std::string& name, bool marker) {
  const std::string path = stagedPath(name, marker);
  File& f = files_[name];
  f.stream = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc);
  if (!*f.stream) throw std::runtime_error(folder_ + "/" + name + ": cannot open for writing");
  f.stream->precision(12);
  return *f.stream;
}

std::uintmax_t OutputSet::close(const std::string& name) {
  File& f = files_.at(name);
  if (f.stream) {
    f.stream->flush();
    if (!*f.stream) throw std::runtime_error(folder_ + "/" + name + ": write failed");
    f.stream->close();
    f.stream.reset();
  }
  return fs::file_size(fs::path(staging_) / name);
}

void OutputSet::commit() {
  for (auto& [name, f] : files_) close(name);
  // Every file under the staging folder belongs to the set, also those writers put there by path.
  std::map<std::string, bool> staged;  // name -> marker
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(staging_)) {
    if (!e.is_regular_file()) continue;
    const std::string name = fs::relative(e.path(), staging_).string();
    const auto it = files_.find(name);
    staged[name] = it != files_.end() && it->second.marker;
  }
  for (const auto& [name, marker] : staged) {
    if (marker) fs::remove(fs::path(folder_) / name);
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (const auto& [name, marker] : staged) {
      if (marker != (pass == 1)) continue;
      const fs::path to = fs::path(folder_) / name;
      fs::create_directories(to.parent_path());
      std::error_code ec;
      fs::rename(fs::path(staging_) / name, to, ec);
      if (ec) throw std::runtime_error(to.string() + ": cannot move into place: " + ec.message());
    }
  }
  committed_ = true;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

std::map<std::string, std::uintmax_t> verifyOutputSet(const std::string& summary_path) {
  const fs::path folder = fs::path(summary_path).parent_path();
  std::ifstream in(summary_path);
  if (!in) {
    throw DataError(summary_path, 0,
                    "missing: the outputs in this folder are incomplete (an interrupted run?)");
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw DataError(summary_path, 0, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("files") || !j["files"].is_object()) {
    throw DataError(summary_path, 0, "no \"files\" list (written by an older giocal?)");
  }
  std::map<std::string, std::uintmax_t> files;
  for (const auto& [name, size] : j["files"].items()) {
    const fs::path p = folder / name;
    std::error_code ec;
    const std::uintmax_t actual = fs::file_size(p, ec);
    if (ec) throw DataError(summary_path, 0, "lists " + name + ", which is missing");
    if (!size.is_number_unsigned() || actual != size.get<std::uintmax_t>()) {
      throw DataError(summary_path, 0,
                      "lists " + name + " of " + size.dump() + " bytes but it has " +
                          std::to_string(actual) + ": the folder mixes outputs of two runs");
    }
    files[name] = actual;
  }
  return files;
}

}  // namespace giocal
