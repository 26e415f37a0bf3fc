// Reader of RINEX observation files 2.10/2.11 and 3.02-3.05 (GPS, Galileo, BeiDou, QZSS kept;
// GLONASS and SBAS parsed and dropped). Event flags 2-5 and cycle-slip records (6) are skipped.
#pragma once

#include <memory>
#include <string>

#include "common/gnss/observation.h"

namespace giocal {

/// Reads an observation file epoch by epoch (constant memory): the header on construction, then
/// one epoch per next(). Same checks as readRinexObs().
class RinexObsReader {
 public:
  explicit RinexObsReader(const std::string& path);
  ~RinexObsReader();
  RinexObsReader(const RinexObsReader&) = delete;
  RinexObsReader& operator=(const RinexObsReader&) = delete;

  const ObsHeader& header() const;
  /// The next epoch (special records skipped); false at the end of the file.
  bool next(ObsEpoch& epoch);
  int skippedSpecialRecords() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// Throws DataError naming the file, the line and the problem (truncated or malformed records,
/// epochs out of order); never hangs on a bad file.
ObsData readRinexObs(const std::string& path);

}  // namespace giocal
