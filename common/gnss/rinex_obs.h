// Reader of RINEX observation files 2.10/2.11 and 3.02-3.05 (GPS, Galileo, BeiDou, QZSS kept;
// GLONASS and SBAS parsed and dropped). Event flags 2-5 and cycle-slip records (6) are skipped.
#pragma once

#include <string>

#include "common/gnss/observation.h"

namespace giocal {

/// Throws DataError naming the file, the line and the problem (truncated or malformed records,
/// epochs out of order); never hangs on a bad file.
ObsData readRinexObs(const std::string& path);

}  // namespace giocal
