#include "common/io/dataset_folder.h"

#include <filesystem>

#include "common/io/csv_table.h"

namespace giocal {

bool DatasetFolder::hasTruthTrajectory() const {
  return !description.truth.empty() && std::filesystem::exists(path(description.truth));
}

DatasetFolder openDatasetFolder(const std::string& folder) {
  DatasetFolder d;
  d.folder = folder;
  d.description = readDatasetDescription(folder);
  const std::string truth = folder + "/truth_calib.yaml";
  if (std::filesystem::exists(truth)) d.truth = readTruthCalibration(truth);
  const std::string scenes = folder + "/scenes.csv";
  if (std::filesystem::exists(scenes)) d.scenes = readScenesCsv(scenes);
  if (const auto span = csvTimeSpan(d.path(d.description.imu))) d.imu_span = *span;
  const DatasetDescription& f = d.description;
  std::vector<std::string> named{f.imu, f.odom, f.rover_obs, f.base_obs, f.truth};
  named.insert(named.end(), f.nav.begin(), f.nav.end());
  for (const std::string& n : named) {
    if (!n.empty() && !std::filesystem::exists(d.path(n))) d.missing.push_back(n);
  }
  return d;
}

}  // namespace giocal
