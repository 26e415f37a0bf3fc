// Satellite identifiers and constellation constants (frequencies, wavelengths).
#pragma once

#include <string>

namespace giocal {

enum class GnssSystem : char {
  kGps = 'G',
  kGlonass = 'R',
  kGalileo = 'E',
  kBeidou = 'C',
  kQzss = 'J',
  kSbas = 'S',
  kIrnss = 'I'
};

struct SatId {
  GnssSystem sys = GnssSystem::kGps;
  int prn = 0;

  bool operator<(const SatId& o) const {
    return sys != o.sys ? static_cast<char>(sys) < static_cast<char>(o.sys) : prn < o.prn;
  }
  bool operator==(const SatId& o) const { return sys == o.sys && prn == o.prn; }
  bool operator!=(const SatId& o) const { return !(*this == o); }
  /// "G05", "E11", ...
  std::string str() const;
};

/// Parses "G05", "G 5", " 5" (RINEX 2: blank means GPS), "E11"; false when not a satellite id.
bool parseSatId(const std::string& text, SatId& out);
/// True for the systems giocal processes (GPS, Galileo, BeiDou, QZSS).
bool isSupported(GnssSystem sys);

constexpr double kSpeedOfLight = 299792458.0;

/// Carrier frequency [Hz] of a RINEX 3 band digit for a system (GLONASS FDMA unsupported: 0).
double carrierFrequency(GnssSystem sys, char band);

/// The primary single-frequency band (SPP, Doppler, the transmission time, the slip pairs):
/// L1/E1 for GPS, QZSS and Galileo, B1I for BeiDou.
inline char primaryBand(GnssSystem sys) { return sys == GnssSystem::kBeidou ? '2' : '1'; }

/// BeiDou GEO satellites (their orbits use a different frame rotation).
bool isBeidouGeo(const SatId& sat);

}  // namespace giocal
