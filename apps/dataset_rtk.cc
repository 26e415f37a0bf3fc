#include "apps/dataset_rtk.h"

#include <unistd.h>

#include <filesystem>

namespace giocal {

RtkJob datasetRtkJob(const DatasetDescription& d, const GiocalConfig& config,
                     const std::string& out, const StopRequest* stop) {
  RtkJob job;
  job.rover = d.pathOf(d.rover_obs);
  job.base = d.pathOf(d.base_obs);
  for (const std::string& n : d.nav) job.nav.push_back(d.pathOf(n));
  job.base_pos = d.base_position_ecef;
  job.options = config.rtk;
  job.out = out;
  job.stop = stop;
  return job;
}

TempPosFile::TempPosFile(const std::string& purpose)
    : path((std::filesystem::temp_directory_path() /
            ("giocal_" + purpose + "_" + std::to_string(::getpid()) + ".pos"))
               .string()) {}

TempPosFile::~TempPosFile() {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

}  // namespace giocal
