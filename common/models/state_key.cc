#include "common/models/state_key.h"

namespace giocal {

namespace {

const char* quantityName(Quantity q) {
  switch (q) {
    case Quantity::kPosition:
      return "p_n_b";
    case Quantity::kVelocity:
      return "v_n_b";
    case Quantity::kAttitude:
      return "q_n_b";
    case Quantity::kAccelBias:
      return "b_a";
    case Quantity::kGyroBias:
      return "b_g";
    case Quantity::kSpeedScale:
      return "s_v";
    case Quantity::kYawRateScale:
      return "s_w";
    case Quantity::kOdometerLever:
      return "p_b_m";
    case Quantity::kOdometerMount:
      return "q_b_m";
    case Quantity::kAntennaLever:
      return "p_b_g";
    case Quantity::kOdometerDelay:
      return "t_d_odo";
    case Quantity::kGyroTilt:
      return "gyro_tilt";
    case Quantity::kClockDrift:
      return "cdt_dot";
    case Quantity::kAmbiguity:
      return "N";
    case Quantity::kTdcpDrift:
      return "v_tdcp";
    case Quantity::kSppBias:
      return "b_spp";
  }
  return "?";
}

const char* copySuffix(Copy c) {
  switch (c) {
    case Copy::kNow:
      return "";
    case Copy::kI:
      return "@i";
    case Copy::kJ:
      return "@j";
    case Copy::kStill:
      return "@still";
    case Copy::kOdo:
      return "@odo";
    case Copy::kGnss:
      return "@gnss";
  }
  return "@?";
}

}  // namespace

std::string StateKey::str() const {
  std::string s = quantityName(what);
  if (what == Quantity::kAmbiguity) {
    s += ':' + sat.str() + ':' + band;
    if (version > 0) s += '#' + std::to_string(version);
  }
  s += copySuffix(copy);
  if (epoch >= 0) s += '#' + std::to_string(epoch);
  return s;
}

}  // namespace giocal
