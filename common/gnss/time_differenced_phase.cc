#include "common/gnss/time_differenced_phase.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "common/gnss/atmosphere.h"
#include "common/io/text.h"

namespace giocal {

namespace {

// A common jump of code minus phase this large is a receiver clock step, not noise or multipath
// (u-blox receivers step by a millisecond, 300 km).
constexpr double kClockJump_m = 1.0e4;

bool usesSystem(const TdcpOptions& o, GnssSystem sys) {
  return std::find(o.systems.begin(), o.systems.end(), sys) != o.systems.end();
}

// The same signal (band and attribute) with phase at both epochs, or nullptr.
const SignalObs* sameSignal(const SatObs& now, const SatObs& before, char band,
                            const SignalObs** earlier) {
  const SignalObs* s1 = now.bestOnBand(band);
  if (!s1 || !std::isfinite(s1->L)) return nullptr;
  for (const SignalObs& s0 : before.signals) {
    if (s0.band == band && s0.attr == s1->attr && std::isfinite(s0.L)) {
      *earlier = &s0;
      return s1;
    }
  }
  return nullptr;
}

}  // namespace

void TdcpCounts::add(const TdcpCounts& o) {
  slipped += o.slipped;
  half_cycle += o.half_cycle;
  low += o.low;
  no_orbit += o.no_orbit;
  alone += o.alone;
  ephemeris_changes += o.ephemeris_changes;
  gaps += o.gaps;
  clock_jumps += o.clock_jumps;
  screened += o.screened;
  broken += o.broken;
}

double tdcpObserved(const TdcpPair& pair, const TdcpRow& row) {
  return pair.signals[static_cast<size_t>(row.signal)].phase_change_m -
         pair.signals[static_cast<size_t>(row.ref)].phase_change_m;
}

double tdcpPredict(const TdcpPair& pair, const TdcpRow& row, const Eigen::Vector3d& p0_e,
                   const Eigen::Vector3d& p1_e, Eigen::RowVector3d* d_p0,
                   Eigen::RowVector3d* d_p1) {
  double value = 0.0;
  if (d_p0) d_p0->setZero();
  if (d_p1) d_p1->setZero();
  for (const auto& [index, sign] : {std::pair{row.signal, 1.0}, std::pair{row.ref, -1.0}}) {
    const TdcpSignal& s = pair.signals[static_cast<size_t>(index)];
    const Eigen::Vector3d r1 = s.sat1_e - p1_e, r0 = s.sat0_e - p0_e;
    value += sign * (r1.norm() - r0.norm() - s.sat_clock_change_m + s.tropo_change_m);
    if (d_p0) *d_p0 += sign * r0.normalized().transpose();
    if (d_p1) *d_p1 -= sign * r1.normalized().transpose();
  }
  return value;
}

Eigen::MatrixXd tdcpCovariance(const TdcpPair& pair) {
  const long m = static_cast<long>(pair.rows.size());
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(m, m);
  for (long a = 0; a < m; ++a) {
    const TdcpRow& ra = pair.rows[static_cast<size_t>(a)];
    C(a, a) = pair.signals[static_cast<size_t>(ra.signal)].variance;
    for (long b = 0; b < m; ++b) {
      if (pair.rows[static_cast<size_t>(b)].ref == ra.ref)
        C(a, b) += pair.signals[static_cast<size_t>(ra.ref)].variance;
    }
  }
  return C;
}

int formRows(TdcpPair& pair) {
  pair.rows.clear();
  // Reference per system and band: the highest signal. Rows difference every other against it.
  std::map<std::pair<GnssSystem, char>, int> refs;
  for (size_t i = 0; i < pair.signals.size(); ++i) {
    const TdcpSignal& g = pair.signals[i];
    const auto key = std::make_pair(g.sat.sys, g.band);
    const auto it = refs.find(key);
    if (it == refs.end() || pair.signals[static_cast<size_t>(it->second)].el < g.el)
      refs[key] = static_cast<int>(i);
  }
  for (size_t i = 0; i < pair.signals.size(); ++i) {
    const TdcpSignal& g = pair.signals[i];
    const int ref = refs.at({g.sat.sys, g.band});
    if (ref != static_cast<int>(i)) pair.rows.push_back({static_cast<int>(i), ref});
  }
  int groups_alone = 0;
  for (const auto& [key, ref] : refs) {
    const bool alone = std::none_of(pair.rows.begin(), pair.rows.end(),
                                    [&](const TdcpRow& r) { return r.ref == ref; });
    if (alone) ++groups_alone;
  }
  return groups_alone;
}

void dropRowSignal(TdcpPair& pair, long row) {
  pair.signals.erase(pair.signals.begin() + pair.rows[static_cast<size_t>(row)].signal);
  formRows(pair);
  if (pair.rows.size() < 3) pair.rows.clear();
}

int screenTdcp(TdcpPair& pair, const Eigen::Vector3d& p0_e, const Eigen::Vector3d& p1_e,
               double predicted_sigma_m, double gate) {
  // Each signal's phase change less the predicted range change: the receiver clock's change
  // (per system and band) plus noise, and a slip or multipath jump where one is.
  std::map<std::pair<GnssSystem, char>, std::vector<double>> by_clock;
  std::vector<double> misfit(pair.signals.size());
  for (size_t i = 0; i < pair.signals.size(); ++i) {
    const TdcpSignal& s = pair.signals[i];
    misfit[i] = s.phase_change_m - ((s.sat1_e - p1_e).norm() - (s.sat0_e - p0_e).norm() -
                                    s.sat_clock_change_m + s.tropo_change_m);
    by_clock[{s.sat.sys, s.band}].push_back(misfit[i]);
  }
  std::map<std::pair<GnssSystem, char>, double> clock;
  for (auto& [key, values] : by_clock) {
    if (values.size() < 3) continue;  // two cannot tell which one is wrong
    auto mid = values.begin() + static_cast<long>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    clock[key] = *mid;
  }
  std::vector<TdcpSignal> kept;
  for (size_t i = 0; i < pair.signals.size(); ++i) {
    const TdcpSignal& s = pair.signals[i];
    const auto it = clock.find({s.sat.sys, s.band});
    const double sigma = std::sqrt(s.variance + predicted_sigma_m * predicted_sigma_m);
    if (it != clock.end() && std::abs(misfit[i] - it->second) > gate * sigma) {
      ++pair.left_out.screened;
      continue;
    }
    kept.push_back(s);
  }
  const int dropped = static_cast<int>(pair.signals.size() - kept.size());
  if (dropped > 0) {
    pair.signals = std::move(kept);
    formRows(pair);
  }
  return dropped;
}

std::string brokenSatelliteWarning(const SatId& sat, int slips_in_a_row, double t) {
  return "satellite " + sat.str() + ": its carrier phase slipped in " +
         std::to_string(slips_in_a_row) + " epochs in a row up to t=" + timeText(t) +
         "; left out of the time-differenced phase from then on (counter tdcp_slips)";
}

std::vector<SatId> TdcpBuilder::takeNewlyBroken() {
  std::vector<SatId> out;
  out.swap(newly_broken_);
  return out;
}

TdcpBuilder::TdcpBuilder(const BroadcastOrbits& orbits, const TdcpOptions& options)
    : orbits_(orbits),
      options_(options),
      slips_(options.slips),
      ionosphere_(options.ionosphere_window_s, options.ionosphere_min_span_s) {}

TdcpPair TdcpBuilder::add(const ObsEpoch& epoch, const Eigen::Vector3d& rover_e) {
  slips_.update(epoch);
  TdcpPair out;
  out.t0 = previous_.t;
  out.t1 = epoch.t;
  // Positions off the Earth (none known at one of the epochs) pair nothing.
  const bool located = previous_e_.norm() > 6.0e6 && rover_e.norm() > 6.0e6;
  const bool paired = has_previous_ && located && epoch.t > previous_.t &&
                      epoch.t - previous_.t <= options_.max_interval_s && epoch.flag != 1;
  if (has_previous_ && !paired) ++out.left_out.gaps;
  const double mask = options_.elevation_mask_deg * M_PI / 180.0;
  const Eigen::Vector3d& before_e = paired ? previous_e_ : rover_e;
  const Topocentric sky0(before_e), sky1(rover_e);
  const Geodetic geo0 = geodeticFromEcef(before_e), geo1 = geodeticFromEcef(rover_e);
  std::vector<double> code_minus_phase;
  const std::vector<SatObs> none;
  for (const SatObs& now : paired ? epoch.sats : none) {
    if (!usesSystem(options_, now.sat.sys)) continue;
    const SatObs* before = previous_.find(now.sat);
    if (!before) continue;
    const char primary = primaryBand(now.sat.sys);
    const SignalObs* c1 = now.bestOnBand(primary);
    const SignalObs* c0 = before->bestOnBand(primary);
    if (!c1 || !c0 || !std::isfinite(c1->P) || !std::isfinite(c0->P)) continue;
    // One ephemeris for both epochs: a new issue of data between them would jump the range.
    const Ephemeris* eph = orbits_.select(now.sat, epoch.t);
    if (!eph) {
      ++out.left_out.no_orbit;
      continue;
    }
    if (orbits_.select(now.sat, previous_.t) != eph) ++out.left_out.ephemeris_changes;
    const SatelliteAtReception at1 =
        BroadcastOrbits::atReception(*eph, epoch.t, c1->P, c1->band, rover_e);
    const SatelliteAtReception at0 =
        BroadcastOrbits::atReception(*eph, previous_.t, c0->P, c0->band, previous_e_);
    double el0 = 0, el1 = 0, az = 0;
    sky0.elevationAzimuth(at0.p_e, el0, az);
    sky1.elevationAzimuth(at1.p_e, el1, az);
    if (el1 < mask) {
      ++out.left_out.low;
      continue;
    }
    if (broken_.count(now.sat)) {
      ++out.left_out.broken;
      continue;
    }
    for (char band : ddBands(now.sat.sys, options_.frequencies)) {
      const SignalObs* s0 = nullptr;
      const SignalObs* s1 = sameSignal(now, *before, band, &s0);
      const double f = carrierFrequency(now.sat.sys, band);
      if (!s1 || f <= 0.0) continue;
      if ((s1->lli & 2) || (s0->lli & 2)) {
        ++out.left_out.half_cycle;
        continue;
      }
      if (slips_.slipped(now.sat, band)) {
        ++out.left_out.slipped;
        if (out.slipped.empty() || out.slipped.back() != now.sat) out.slipped.push_back(now.sat);
        continue;
      }
      TdcpSignal g;
      g.sat = now.sat;
      g.band = band;
      g.lambda = kSpeedOfLight / f;
      g.sat0_e = at0.p_e;
      g.sat1_e = at1.p_e;
      g.sat_clock_change_m = kSpeedOfLight * (at1.clock - at0.clock);
      g.tropo_change_m = tropoSaastamoinen(geo1, el1) - tropoSaastamoinen(geo0, el0);
      g.phase_change_m = g.lambda * (s1->L - s0->L);
      g.variance = 2.0 * options_.phase.variance(el1);
      g.el = el1;
      if (band == primary) code_minus_phase.push_back((c1->P - c0->P) - g.phase_change_m);
      out.signals.push_back(g);
    }
  }
  if (!code_minus_phase.empty()) {
    auto mid = code_minus_phase.begin() + static_cast<long>(code_minus_phase.size() / 2);
    std::nth_element(code_minus_phase.begin(), mid, code_minus_phase.end());
    if (std::abs(*mid) > kClockJump_m) ++out.left_out.clock_jumps;
  }
  ionosphere_.correct(out);
  out.left_out.alone += formRows(out);
  // Satellites that slipped in this pair, and in every one before it up to the limit.
  for (const SatObs& now : paired ? epoch.sats : none) {
    const bool slipped =
        std::find(out.slipped.begin(), out.slipped.end(), now.sat) != out.slipped.end();
    int& run = slips_in_a_row_[now.sat];
    run = slipped ? run + 1 : 0;
    if (run >= options_.max_slips_in_a_row && broken_.insert(now.sat).second)
      newly_broken_.push_back(now.sat);
  }
  totals_.add(out.left_out);
  previous_ = epoch;
  previous_e_ = rover_e;
  has_previous_ = true;
  return out;
}

}  // namespace giocal
