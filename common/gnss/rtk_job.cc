#include "common/gnss/rtk_job.h"

#include <chrono>
#include <sstream>
#include <stdexcept>

#include "common/gnss/pos_file.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/io/data_error.h"

namespace giocal {

Eigen::Vector3d parseBasePosition(const std::string& text, const std::string& flag) {
  std::stringstream ss(text);
  std::string part;
  std::vector<double> v;
  while (std::getline(ss, part, ',')) {
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0')
      throw std::invalid_argument(flag + ": '" + text + "' is not x,y,z");
    v.push_back(x);
  }
  const Eigen::Vector3d p =
      v.size() == 3 ? Eigen::Vector3d(v[0], v[1], v[2]) : Eigen::Vector3d::Zero();
  if (v.size() != 3 || p.norm() < 6.0e6 || p.norm() > 6.5e6) {
    throw std::invalid_argument(flag + ": '" + text +
                                "' is not an ECEF x,y,z near the Earth's surface");
  }
  return p;
}

RtkSummary runRtk(const RtkJob& job, std::vector<RtkSolution>* out_solutions) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<NavData> navs;
  for (const auto& n : job.nav) navs.push_back(readRinexNav(n));
  const BroadcastOrbits orbits(mergeNav(navs));
  const ObsData rover = readRinexObs(job.rover);
  const ObsData base = readRinexObs(job.base);
  Eigen::Vector3d base_e = job.base_pos ? *job.base_pos : base.header.approx_position;
  if (base_e.norm() < 6.0e6) {
    throw DataError(job.base, 0, "no APPROX POSITION XYZ in the header; give --base-pos x,y,z");
  }
  RtkFilter filter(orbits, base_e, job.options);
  std::vector<RtkSolution> sols;
  RtkSummary sum;
  sum.warnings = rover.warnings;
  sum.warnings.insert(sum.warnings.end(), base.warnings.begin(), base.warnings.end());
  BaseEpochMatcher matcher(base.epochs, job.options.max_base_offset);
  for (const ObsEpoch& e : rover.epochs) {
    checkStop(job.stop);
    const RtkSolution s = filter.process(e, matcher.nearest(e.t));
    ++sum.epochs;
    sum.fixed += s.quality == 1;
    sum.floats += s.quality == 2;
    sum.single += s.quality == 5;
    sols.push_back(s);
  }
  PosHeader header;
  header.inputs = {job.rover, job.base};
  header.inputs.insert(header.inputs.end(), job.nav.begin(), job.nav.end());
  header.base_e = base_e;
  writePosFile(job.out, header, sols);
  if (!rover.epochs.empty()) sum.data_s = rover.epochs.back().t - rover.epochs.front().t;
  sum.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (out_solutions) *out_solutions = std::move(sols);
  return sum;
}

}  // namespace giocal
