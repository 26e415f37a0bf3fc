// Reader of RINEX observation files 2.10/2.11 and 3.02-3.05 (GPS, Galileo, BeiDou, QZSS kept;
// GLONASS and SBAS parsed and dropped). Event flags 2-5 and cycle-slip records (6) are skipped.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/gnss/observation.h"
#include "common/gnss/phase_alignment.h"

namespace giocal {

/// Reads an observation file epoch by epoch (constant memory): the header on construction, then
/// one epoch per next(). Same checks as readRinexObs(). Where a band has several phase signals,
/// the construction reads the file once more to check that they are aligned (phase_alignment.h)
/// and next() aligns a signal a quarter or half cycle off, with a warning.
class RinexObsReader {
 public:
  explicit RinexObsReader(const std::string& path) : RinexObsReader(path, true) {}
  ~RinexObsReader();
  RinexObsReader(const RinexObsReader&) = delete;
  RinexObsReader& operator=(const RinexObsReader&) = delete;

  const ObsHeader& header() const;
  /// The next epoch (special records skipped); false at the end of the file. Recoverable damage
  /// is dropped and listed by warnings(): an epoch repeating the previous time or going back (up
  /// to 10 in a row), a last epoch the file ends inside.
  bool next(ObsEpoch& epoch);
  int skippedSpecialRecords() const;
  std::vector<std::string> warnings() const;
  /// The alignment check's findings per signal (empty with one phase signal per band).
  const std::vector<SignalOffset>& phaseOffsets() const;

 private:
  RinexObsReader(const std::string& path, bool align);
  bool nextEpoch(ObsEpoch& epoch);
  struct State;
  std::unique_ptr<State> s_;
};

/// Throws DataError naming the file, the line and the problem (truncated or malformed records,
/// epochs out of order); never hangs on a bad file.
ObsData readRinexObs(const std::string& path);

}  // namespace giocal
