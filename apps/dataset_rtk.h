// The dataset's own RTK solution, for the commands that need one as a reference or start
// (validate, calibrate's check at its end, observability): the job over its rover, base and
// navigation files, and a temporary .pos file removed with its owner.
#pragma once

#include <string>

#include "common/gnss/rtk_job.h"
#include "common/io/dataset_description.h"
#include "options/giocal_config.h"

namespace giocal {

/// RTK over the dataset's files with the configuration's `rtk` options, into `out`.
RtkJob datasetRtkJob(const DatasetDescription& d, const GiocalConfig& config,
                     const std::string& out, const StopRequest* stop = nullptr);

/// A temporary .pos file (named after `purpose` and the process), removed with the object.
struct TempPosFile {
  explicit TempPosFile(const std::string& purpose);
  ~TempPosFile();
  TempPosFile(const TempPosFile&) = delete;
  TempPosFile& operator=(const TempPosFile&) = delete;
  std::string path;
};

}  // namespace giocal
