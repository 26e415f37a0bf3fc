#include "import/ubx_log.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "import/galileo_inav.h"
#include "import/gps_lnav.h"
#include "import/observation_log.h"
#include "import/payload_reader.h"
#include "import/ubx_signals.h"

namespace giocal::import {

namespace {

constexpr uint8_t kClassRxm = 0x02;
constexpr uint8_t kIdRawx = 0x15;
constexpr uint8_t kIdSfrbx = 0x13;
constexpr std::size_t kMaxEarlySubframes = 2000;

void readSubframe(const UbxFrame& f, double t_rx, NavAssemblers& nav, UbxLog& log) {
  ++log.subframes;
  const PayloadReader p(f.payload);
  if (p.size() < 8 || p.size() != 8 + 4 * static_cast<std::size_t>(p.u1(4))) {
    ++log.subframes_rejected;
    return;
  }
  SatId sat;
  const int gnss = p.u1(0), sig = p.u1(2);
  if (!ubxSatellite(gnss, p.u1(1), sat)) {
    ++log.subframes_not_read;
    return;
  }
  std::vector<uint32_t> words;
  for (std::size_t k = 0; k < p.u1(4); ++k) words.push_back(p.u4(8 + 4 * k));
  try {
    std::optional<Ephemeris> eph;
    if ((sat.sys == GnssSystem::kGps || sat.sys == GnssSystem::kQzss) && sig == 0) {
      eph = nav.lnav.add(sat, words, t_rx);
    } else if (sat.sys == GnssSystem::kGalileo && (sig == 1 || sig == 5 || sig == 0)) {
      // I/NAV is on E1-B (1) and E5b-I (5); 0 is what drivers that leave this byte reserved
      // report. The pages' CRC tells I/NAV from anything else.
      eph = nav.inav.add(sat, words, t_rx);
    } else if (sat.sys == GnssSystem::kBeidou && sig >= 0 && sig <= 4) {
      // B1I (D1 0, D2 1), B2I (2, 3) and B3I (4 on the X20): the GEO satellites broadcast D2,
      // the MEO and IGSO satellites D1, on each of them.
      eph = isBeidouGeo(sat) ? nav.d2.add(sat, words, t_rx) : nav.d1.add(sat, words, t_rx);
    } else {
      ++log.subframes_not_read;
      return;
    }
    if (eph) log.nav.ephemerides.push_back(*eph);
  } catch (const std::exception&) {
    ++log.subframes_rejected;
  }
}

}  // namespace

UbxDecoder::UbxDecoder(std::string source) : source_(std::move(source)) {}

void UbxDecoder::add(const UbxFrame& f, const std::string& where) {
  if (f.cls == kClassRxm && f.id == kIdRawx) {
    try {
      ObsEpoch e = rawx_.decode(f.payload);
      if (!log_.obs.epochs.empty() && e.t <= log_.obs.epochs.back().t) {
        if (log_.epochs_out_of_order++ == 0) first_out_of_order_ = where;
        return;
      }
      log_.obs.epochs.push_back(std::move(e));
    } catch (const std::exception& ex) {
      if (log_.rawx_rejected++ == 0)
        log_.warnings.push_back(source_ + ": " + where + ": " + ex.what());
    }
  } else if (f.cls == kClassRxm && f.id == kIdSfrbx) {
    // Subframes before the first epoch wait for its time (they need it for their week).
    if (log_.obs.epochs.empty()) {
      if (early_.size() < kMaxEarlySubframes) {
        early_.push_back(f);
      } else {
        ++log_.subframes_not_read;
      }
      return;
    }
    for (const UbxFrame& e : early_) readSubframe(e, log_.obs.epochs.back().t, nav_, log_);
    early_.clear();
    readSubframe(f, log_.obs.epochs.back().t, nav_, log_);
  } else {
    ++log_.other_messages;
  }
}

UbxLog UbxDecoder::finish(const UbxStreamCounts& stream) {
  UbxLog log = std::move(log_);
  if (const auto& iono = nav_.lnav.ionosphere()) {
    log.nav.gps_iono = *iono;
    log.nav.has_gps_iono = true;
  }
  log.stream = stream;
  log.rawx = rawx_.counts();
  if (log.obs.epochs.empty()) throw std::runtime_error(source_ + ": no UBX-RXM-RAWX epoch");
  if (log.stream.bad_checksums > 0) {
    log.warnings.push_back(source_ + ": byte " + std::to_string(log.stream.first_bad_offset) +
                           ": " + std::to_string(log.stream.bad_checksums) +
                           " frames with a bad checksum skipped (first here)");
  }
  if (log.stream.truncated_end) log.warnings.push_back(source_ + ": the log ends inside a frame");
  if (log.epochs_out_of_order > 0) {
    log.warnings.push_back(source_ + ": " + first_out_of_order_ + ": " +
                           std::to_string(log.epochs_out_of_order) +
                           " RAWX epochs not after the previous one dropped (time going "
                           "backwards or repeated; first here)");
  }
  if (log.subframes_rejected > 0) {
    log.warnings.push_back(source_ + ": " + std::to_string(log.subframes_rejected) +
                           " navigation subframes rejected (bad CRC, not LNAV, part order)");
  }
  log.obs.header.marker = "UBX";
  describeObservations(log.obs);
  return log;
}

UbxLog readUbxLog(const std::string& path, const std::function<void(double)>& progress) {
  UbxStream stream(path);
  UbxDecoder decoder(path);
  std::error_code ec;
  const double size = static_cast<double>(std::filesystem::file_size(path, ec));
  UbxFrame f;
  for (long n = 1; stream.next(f); ++n) {
    decoder.add(f, "byte " + std::to_string(f.offset));
    if (progress && !ec && size > 0.0 && n % 1000 == 0) {
      progress(static_cast<double>(f.offset) / size);
    }
  }
  return decoder.finish(stream.counts());
}

}  // namespace giocal::import
