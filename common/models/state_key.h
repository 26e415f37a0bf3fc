// StateKey: the typed name of a state variable, one vocabulary for the measurement models, the
// EKF's registry and the factor graph's window: what it is, which copy, epoch, satellite and band.
#pragma once

#include <climits>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "common/gnss/satellite.h"

namespace giocal {

enum class Quantity : std::uint8_t {
  kPosition,       // p_n_b [m]
  kVelocity,       // v_n_b [m/s]
  kAttitude,       // q_n_b
  kAccelBias,      // b_a [m/s^2]
  kGyroBias,       // b_g [rad/s]
  kSpeedScale,     // s_v
  kYawRateScale,   // s_w
  kOdometerLever,  // p_b_m [m]
  kOdometerMount,  // q_b_m
  kAntennaLever,   // p_b_g [m]
  kOdometerDelay,  // t_d_odo [s], the odometer's delay against the IMU
  kGyroTilt,       // the gyro triad's tilt against the accelerometer's (x, y) [rad]
  kClockDrift,     // cdt_dot [m/s]
  kAmbiguity,      // N, a single-differenced carrier-phase ambiguity [cycles]
  kTdcpDrift,      // one receiver's time differences' slow error as an antenna velocity (ENU)
                   // [m/s]: the satellites' clock and orbit rates, seen through the geometry
  kSppBias,        // one receiver's single point positions' slow error (ENU) [m]: broadcast
                   // orbits, clocks and atmosphere models, seen through the geometry
};

/// Which copy of a quantity: the current one, a two-state model's start (i) and end (j), or the
/// EKF's stochastic clones (the attitude when the robot stopped, the pose at the start of an
/// odometer interval, the pose at the previous GNSS epoch for time-differenced phase).
enum class Copy : std::uint8_t { kNow, kI, kJ, kStill, kOdo, kGnss };

struct StateKey {
  Quantity what = Quantity::kPosition;
  Copy copy = Copy::kNow;
  int epoch = -1;  // the factor graph's GNSS epoch number; -1 for a state without one
  SatId sat{};     // ambiguities: the satellite, its band and the ambiguity's version (it
  char band = 0;   // restarts after a cycle slip)
  int version = 0;

  /// "p_n_b", "q_n_b@i", "s_v#12", "N:G05:1", "N:G05:1#3": for messages and logs only.
  std::string str() const;

  auto tie() const { return std::tie(what, copy, epoch, sat.sys, sat.prn, band, version); }
  /// The key as two integers that compare as tie() does (each field offset to unsigned, in
  /// tie()'s order): a look-up's comparisons are then two integer compares each.
  std::pair<std::uint64_t, std::uint64_t> ordinal() const {
    const auto u8 = [](char v) { return std::uint64_t(std::uint8_t(int(v) - CHAR_MIN)); };
    const auto u32 = [](int v) { return std::uint64_t(std::uint32_t(v) ^ 0x80000000u); };
    const std::uint64_t prn = u32(sat.prn);
    return {(std::uint64_t(what) << 56) | (std::uint64_t(copy) << 48) | (u32(epoch) << 16) |
                (u8(static_cast<char>(sat.sys)) << 8) | (prn >> 24),
            ((prn & 0xffffffu) << 40) | (u8(band) << 32) | u32(version)};
  }
  bool operator<(const StateKey& o) const { return tie() < o.tie(); }
  bool operator==(const StateKey& o) const { return tie() == o.tie(); }
  bool operator!=(const StateKey& o) const { return !(*this == o); }
};

/// The same quantity at another copy or epoch.
inline StateKey at(StateKey key, Copy copy) {
  key.copy = copy;
  return key;
}
inline StateKey atEpoch(StateKey key, int epoch) {
  key.epoch = epoch;
  return key;
}
inline StateKey ambiguityKey(const SatId& sat, char band, int version = 0) {
  return {Quantity::kAmbiguity, Copy::kNow, -1, sat, band, version};
}

/// The states every estimator in giocal uses.
namespace state {
inline const StateKey kP{Quantity::kPosition};
inline const StateKey kV{Quantity::kVelocity};
inline const StateKey kQ{Quantity::kAttitude};
inline const StateKey kBa{Quantity::kAccelBias};
inline const StateKey kBg{Quantity::kGyroBias};
inline const StateKey kSv{Quantity::kSpeedScale};
inline const StateKey kSw{Quantity::kYawRateScale};
inline const StateKey kPbm{Quantity::kOdometerLever};
inline const StateKey kQbm{Quantity::kOdometerMount};
inline const StateKey kPbg{Quantity::kAntennaLever};
inline const StateKey kTdOdo{Quantity::kOdometerDelay};
inline const StateKey kGyroTilt{Quantity::kGyroTilt};
inline const StateKey kClockDrift{Quantity::kClockDrift};
inline const StateKey kTdcpDrift{Quantity::kTdcpDrift};
inline const StateKey kSppBias{Quantity::kSppBias};
}  // namespace state

}  // namespace giocal
