// The real u-blox F9P walk (data/real/ublox-f9p-walk) as a single receiver: the antenna's
// displacement between consecutive epochs from time-differenced carrier phase alone (no base),
// against the displacement of RTKLIB's RTK solution of the same walk at its fixed epochs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "common/gnss/pos_reader.h"
#include "common/gnss/spp.h"
#include "common/gnss/tdcp_displacement.h"
#include "common/gnss/time_differenced_phase.h"
#include "import/ubx_log.h"

namespace giocal {
namespace {

const std::string kWalk = std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/";

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1))];
}

TEST(TdcpWalk, DisplacementsPerEpochAgreeWithRtklibsFixedSolution) {
  const import::UbxLog log = import::readUbxLog(kWalk + "gnss_1730.ubx");
  const std::vector<PositionFix> rtk = readPosFile(kWalk + "gnss_1730_sf.pos");
  const BroadcastOrbits orbits(log.nav);
  TdcpBuilder builder(orbits);
  std::vector<double> errors, moved;
  int pairs = 0, solved = 0;
  double chi2 = 0;
  int dof = 0;
  Eigen::Vector3d previous_e = Eigen::Vector3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d>> track;  // TDCP-integrated, restarting at gaps
  std::vector<double> window_errors;
  std::vector<double> sig;
  double previous_t = 0;
  for (const ObsEpoch& e : log.obs.epochs) {
    const SppSolution spp = solveSpp(e, orbits, SppOptions{});
    if (!spp.valid) continue;
    const TdcpPair pair = builder.add(e, spp.p_e);
    if (!pair.rows.empty()) {
      ++pairs;
      const TdcpDisplacement disp = solveTdcpDisplacement(pair, previous_e);
      const PositionFix* a = fixAt(rtk, previous_t, kPositionTolerance);
      const PositionFix* b = fixAt(rtk, e.t, kPositionTolerance);
      if (!disp.valid) track.clear();
      if (disp.valid) {
        sig.push_back(std::sqrt(disp.cov.trace()));
        if (track.empty()) track.push_back({previous_t, Eigen::Vector3d::Zero()});
        track.push_back({e.t, track.back().second + disp.d_e});
        if (track.size() > 40) {
          const auto& [t0, x0] = track[track.size() - 41];
          const PositionFix* f0 = fixAt(rtk, t0, kPositionTolerance);
          const PositionFix* f1 = fixAt(rtk, e.t, kPositionTolerance);
          if (f0 && f1 && f0->quality == 1 && f1->quality == 1)
            window_errors.push_back(((track.back().second - x0) - (f1->p_e - f0->p_e)).norm());
        }
        ++solved;
        chi2 += disp.chi2;
        dof += disp.dof;
      }
      if (disp.valid && a && b && a->quality == 1 && b->quality == 1) {
        const Eigen::Vector3d reference = b->p_e - a->p_e;
        errors.push_back((disp.d_e - reference).norm());
        moved.push_back(reference.norm());
      }
    }
    previous_e = spp.p_e;
    previous_t = e.t;
  }
  const TdcpCounts& n = builder.totals();
  std::cout << "F9P walk: " << log.obs.epochs.size() << " epochs, " << solved << " of " << pairs
            << " pairs solved, chi2/dof " << chi2 / dof << "; against " << errors.size()
            << " RTK fixed pairs (median step " << percentile(moved, 0.5) * 1e3
            << " mm): error p50 " << percentile(errors, 0.5) * 1e3 << " mm, p95 "
            << percentile(errors, 0.95) * 1e3 << " mm; left out: slipped " << n.slipped
            << ", half-cycle " << n.half_cycle << ", gaps " << n.gaps << ", clock jumps "
            << n.clock_jumps << ", ephemeris changes " << n.ephemeris_changes << "\n";
  std::cout << "own 3D sigma per step p50 " << percentile(sig, 0.5) * 1e3
            << " mm; TDCP summed over 10 s (40 steps) against RTK: " << window_errors.size()
            << " windows, p50 " << percentile(window_errors, 0.5) * 1e3 << " mm, p95 "
            << percentile(window_errors, 0.95) * 1e3 << " mm\n";
  // Measured: 517 of 534 pairs, chi2/dof 1.18 (the 3 mm phase noise fits this moving consumer
  // receiver), step error p50 28 mm, p95 81 mm against RTKLIB's fixed epochs, whose own
  // per-epoch noise (and 1e-7 degree rounding, 1 cm) is part of it; the walk's geometry is weak
  // (10-12 signals, three clock changes), its own 3D sigma per step p50 21 mm.
  EXPECT_GE(solved, 510);
  EXPECT_GE(errors.size(), 330u);
  EXPECT_LT(chi2 / dof, 1.5);
  EXPECT_LT(percentile(errors, 0.5), 0.035);
  EXPECT_LT(percentile(errors, 0.95), 0.10);
  EXPECT_LT(percentile(window_errors, 0.5), 0.16);
  // Half-cycle phases are left out until resolved; slips are found.
  EXPECT_GT(n.half_cycle, 0);
  EXPECT_GT(n.slipped, 0);
}

}  // namespace
}  // namespace giocal
