// DatasetFolder: a dataset folder opened once per run (its description, the paths of its files,
// the files it names and lacks, its truth and scenes when it has them, the span of its IMU log,
// and what `giocal check` found), handed to whatever needs it.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/io/dataset_description.h"
#include "common/io/scenes_csv.h"

namespace giocal {

struct DatasetFolder {
  std::string folder;
  DatasetDescription description;
  std::optional<TruthCalibration> truth;         // truth_calib.yaml, when there
  std::vector<SceneSpan> scenes;                 // scenes.csv, when there
  std::pair<double, double> imu_span{0.0, 0.0};  // first and last IMU time; {0, 0}: unknown
  std::vector<std::string> missing;  // files dataset.yaml names that are not there, by name
  /// What reading the whole logs found (giocal check): "warning: ..." and "unusable: ..." lines,
  /// each naming its file. A calibration streams the logs and does not fill them.
  std::vector<std::string> findings;
  /// The path of one of its files (a name from the description).
  std::string path(const std::string& name) const { return description.pathOf(name); }
  bool hasTruthTrajectory() const;  // truth.csv named and present
};

/// Reads dataset.yaml (throws DataError as readDatasetDescription does), truth_calib.yaml and
/// scenes.csv when present, and the IMU log's first and last times.
DatasetFolder openDatasetFolder(const std::string& folder);

}  // namespace giocal
