// The RINEX satellite and signal of u-blox identifiers (gnssId, svId, sigId; u-blox F9 interface
// description, "Satellite numbering" and "Signal identifiers").
#pragma once

#include "common/gnss/satellite.h"

namespace giocal::import {

/// The satellite of a gnssId and svId; false for GLONASS, NavIC, unknown systems and numbers out of
/// range (giocal writes GPS, SBAS, Galileo, BeiDou and QZSS).
bool ubxSatellite(int gnss_id, int sv_id, SatId& out);

/// The RINEX 3 band digit and attribute of a sigId; false for a signal giocal does not know.
bool ubxSignal(GnssSystem sys, int sig_id, char& band, char& attr);

}  // namespace giocal::import
