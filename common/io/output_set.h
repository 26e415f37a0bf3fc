// OutputSet: the files of one run, staged in a hidden folder inside the output folder and moved
// into place together when the run completes, so that a folder never holds a mix of two runs.
#pragma once

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace giocal {

class OutputSet {
 public:
  /// Creates `folder` if needed and a staging folder "<folder>/.giocal-partial.<pid>" in it;
  /// staging folders and temporary files that processes no longer running left there (a killed
  /// run) are removed first.
  explicit OutputSet(std::string folder);
  /// Removes the staging folder and everything in it unless commit() completed.
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// A stream onto the staged file `name` (a path relative to the folder, e.g.
  /// "ekf/trajectory.csv"). A marker (a run's summary.json) is moved last and its old version
  /// removed first, so that an interrupted commit leaves files without a marker, which readers
  /// reject (verifyOutputSet).
  std::ostream& open(const std::string& name, bool marker = false);
  /// Flushes and closes a file opened with open(); throws on a write error. Returns its size.
  std::uintmax_t close(const std::string& name);
  /// The staging path of `name` for writers that take a path (the file is part of the set).
  std::string stagedPath(const std::string& name, bool marker = false);

  /// The staging folder, for writers that fill a whole folder (every file in it joins the set).
  const std::string& staging() const { return staging_; }

  /// Closes what is open and moves every file into the folder: old markers removed, other files
  /// renamed over their old versions, markers last. Throws if a file cannot be written or moved.
  void commit();

  const std::string& folder() const { return folder_; }

 private:
  struct File {
    bool marker = false;
    std::unique_ptr<std::ofstream> stream;
  };
  std::string folder_, staging_;
  std::map<std::string, File> files_;
  bool committed_ = false;
};

/// The files a run's summary.json lists under "files" (name -> size in bytes) with their sizes.
/// Throws DataError naming the folder when the summary is missing or a file is missing or of
/// another size: the folder holds an interrupted or mixed set of outputs.
std::map<std::string, std::uintmax_t> verifyOutputSet(const std::string& summary_path);

/// Removes, in `folder`, staging folders and temporary files (io/atomic_file.h) that processes no
/// longer running left; with `of_file`, only the temporaries of that file name.
void sweepStaleTemporaries(const std::string& folder, const std::string& of_file = "");

}  // namespace giocal
