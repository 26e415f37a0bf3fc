// UbxLog: a u-blox UBX log read whole into observations (RXM-RAWX) and broadcast ephemerides
// (RXM-SFRBX: GPS/QZSS LNAV, Galileo I/NAV), with everything skipped or damaged counted.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/gnss/observation.h"
#include "common/gnss/rinex_nav.h"
#include "import/beidou_d1.h"
#include "import/beidou_d2.h"
#include "import/galileo_inav.h"
#include "import/gps_lnav.h"
#include "import/rawx_decoder.h"
#include "import/ubx_stream.h"

namespace giocal::import {

struct UbxLog {
  ObsData obs;  // header.obs_types lists the signals present, per system, C L D S per signal
  NavData nav;
  UbxStreamCounts stream;
  RawxCounts rawx;
  long long rawx_rejected = 0;        // RAWX payloads that were not readable
  long long epochs_out_of_order = 0;  // epochs not after the previous one (dropped)
  long long subframes = 0;            // RXM-SFRBX messages
  long long subframes_rejected = 0;   // bad CRC, not LNAV, part order
  long long subframes_not_read = 0;   // systems and signals without an ephemeris decoder here
  long long other_messages = 0;       // UBX messages other than RAWX and SFRBX
  /// One line per kind of damage or skipped content, naming the file and the first byte offset.
  std::vector<std::string> warnings;
};

/// UBX messages (from a log or a bag's ublox_msgs) in arrival order to observations and
/// ephemerides; warnings name the source and where in it a problem was met.
/// The subframe assemblers of each navigation message giocal reads.
struct NavAssemblers {
  GpsLnavAssembler lnav;
  GalileoInavAssembler inav;
  BeidouD1Assembler d1;
  BeidouD2Assembler d2;
};

class UbxDecoder {
 public:
  explicit UbxDecoder(std::string source);
  UbxDecoder(const UbxDecoder&) = delete;
  UbxDecoder& operator=(const UbxDecoder&) = delete;
  /// One message; `where` names its place in the source ("byte 1234", "message 7 of /rawx").
  void add(const UbxFrame& frame, const std::string& where);
  /// The log; throws std::runtime_error naming the source when it held no RXM-RAWX epoch.
  UbxLog finish(const UbxStreamCounts& stream = {});

 private:
  std::string source_;
  RawxDecoder rawx_;
  NavAssemblers nav_;
  UbxLog log_;
  std::vector<UbxFrame> early_;
  std::string first_out_of_order_;
};

/// Reads the log; throws std::runtime_error naming the file when it has no RXM-RAWX epoch.
/// `progress` (may be empty) is called with the share of the file read (it may throw to stop).
UbxLog readUbxLog(const std::string& path, const std::function<void(double)>& progress = {});

}  // namespace giocal::import
