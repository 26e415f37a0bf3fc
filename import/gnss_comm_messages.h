// GnssCommDecoder: raw GNSS of the gnss_comm ROS messages (the GVINS / Ground-Fusion / M2DGR
// convention: GnssMeasMsg epochs of GnssObsMsg, GnssEphemMsg broadcast ephemerides) to giocal's
// observations and ephemerides.
#pragma once

#include <string>

#include "common/gnss/satellite.h"
#include "import/ros_message.h"
#include "import/ubx_log.h"

namespace giocal::import {

bool isGnssCommMeas(const std::string& type);
bool isGnssCommEphem(const std::string& type);

/// gnss_comm's satellite number (GPS 1-32, GLONASS 33-59, Galileo 60-97, BeiDou 98-160) to a
/// satellite; false for 0 and numbers past BeiDou 63.
bool gnssCommSatellite(long number, SatId& out);
/// The inverse; 0 for satellites gnss_comm has no number for (QZSS, SBAS, IRNSS).
long gnssCommNumber(const SatId& sat);

class GnssCommDecoder {
 public:
  explicit GnssCommDecoder(std::string source) : source_(std::move(source)) {}
  /// One GnssMeasMsg (one epoch); `where` names its place ("topic /meas, message 7").
  void addMeasurements(const RosMessage& m, const std::string& where);
  /// One GnssEphemMsg (GPS, Galileo or BeiDou Keplerian elements; GLONASS has its own type).
  void addEphemeris(const RosMessage& m, const std::string& where);
  /// Observations and ephemerides with what was dropped counted (rawx: the measurement counts);
  /// throws std::runtime_error naming the source when no epoch was read.
  UbxLog finish();

 private:
  std::string source_;
  UbxLog log_;
  std::string first_out_of_order_, first_bad_ephemeris_;
  long long mixed_times_ = 0;
};

}  // namespace giocal::import
