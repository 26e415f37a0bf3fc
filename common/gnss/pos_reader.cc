#include "common/gnss/pos_reader.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/geodesy/wgs84.h"
#include "common/io/data_error.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"

namespace giocal {
namespace {

constexpr double kPrintedResolution = 1e-4;  // [m] of the standard deviations in a .pos

double timeOf(const std::string& a, const std::string& b, const std::string& path, long line) {
  if (a.find('/') != std::string::npos) {
    CalendarTime c;
    double sec = 0.0;
    if (std::sscanf(a.c_str(), "%d/%d/%d", &c.year, &c.month, &c.day) != 3 ||
        std::sscanf(b.c_str(), "%d:%d:%lf", &c.hour, &c.minute, &sec) != 3 || c.year < 1980 ||
        c.year > 2200 || c.month < 1 || c.month > 12 || c.day < 1 || c.day > 31 || c.hour < 0 ||
        c.hour > 23 || c.minute < 0 || c.minute > 59 || !(sec >= 0.0 && sec < 61.0)) {
      throw DataError(path, line, "bad GPST time '" + a + " " + b + "'");
    }
    c.second = sec;
    return gpsSecondsFromCalendar(c);
  }
  char* end = nullptr;
  const double week = std::strtod(a.c_str(), &end);
  const double tow = std::strtod(b.c_str(), nullptr);
  if (end == a.c_str() || !(week >= 0.0 && week <= 9999.0) || week != std::floor(week) ||
      !(tow >= 0.0 && tow < 604800.0)) {
    throw DataError(path, line, "bad GPS week and time of week '" + a + " " + b + "'");
  }
  return week * 604800.0 + tow;
}

}  // namespace

const PositionFix* fixAt(const std::vector<PositionFix>& fixes, double t, double tolerance) {
  auto it = std::lower_bound(fixes.begin(), fixes.end(), t,
                             [](const PositionFix& f, double v) { return f.t < v; });
  const PositionFix* best = nullptr;
  if (it != fixes.end()) best = &*it;
  if (it != fixes.begin() && (!best || t - (it - 1)->t < best->t - t)) best = &*(it - 1);
  return best && std::abs(best->t - t) <= tolerance ? best : nullptr;
}

Eigen::Matrix3d nearestPositiveDefinite(const Eigen::Matrix3d& cov) {
  const Eigen::Vector3d sd = cov.diagonal().cwiseSqrt();
  const Eigen::Matrix3d rho = sd.cwiseInverse().asDiagonal() * cov * sd.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(rho);
  // Floor: a correlation matrix's eigenvalues sum to 3; 1e-3 keeps it well conditioned.
  const Eigen::Matrix3d clipped = eig.eigenvectors() *
                                  eig.eigenvalues().cwiseMax(1e-3).asDiagonal() *
                                  eig.eigenvectors().transpose();
  const Eigen::Vector3d d = clipped.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::Matrix3d corr = d.asDiagonal() * clipped * d.asDiagonal();
  return sd.asDiagonal() * corr * sd.asDiagonal();
}

std::vector<PositionFix> readPosFile(const std::string& path, std::vector<std::string>* warnings) {
  long repaired = 0, first_repaired = 0, zeros = 0, first_zero = 0;
  std::ifstream in(path);
  if (!in) throw DataError(path, 0, "cannot open file");
  std::vector<PositionFix> fixes;
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (text.empty() || text[0] == '%' || text.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::istringstream ss(text);
    std::string a, b;
    double lat, lon, h, q, ns, sdn, sde, sdu, sdne, sdeu, sdun;
    if (!(ss >> a >> b >> lat >> lon >> h >> q >> ns >> sdn >> sde >> sdu >> sdne >> sdeu >>
          sdun)) {
      throw DataError(path, line,
                      "expected: time, latitude, longitude, height, Q, ns, sdn, sde, sdu, sdne, "
                      "sdeu, sdun (RTKLIB .pos with lat/lon/height output)");
    }
    PositionFix f;
    f.t = timeOf(a, b, path, line);
    if (!(std::abs(lat) <= 90.0 && std::abs(lon) <= 360.0 && std::abs(h) < 1e5)) {
      throw DataError(path, line, "latitude, longitude or height out of range");
    }
    if (!(q >= 1.0 && q <= 6.0 && q == std::floor(q) && ns >= 0.0 && ns <= 999.0 &&
          ns == std::floor(ns))) {
      throw DataError(path, line, "Q must be 1-6 and ns a satellite count");
    }
    const double sd[6] = {sdn, sde, sdu, sdne, sdeu, sdun};
    for (double s : sd) {
      if (!std::isfinite(s) || std::abs(s) > 1e4)
        throw DataError(path, line, "bad standard deviation");
    }
    if (!(sdn >= 0.0 && sde >= 0.0 && sdu >= 0.0)) {
      throw DataError(path, line, "sdn, sde and sdu must not be negative");
    }
    // RTKLIB prints 0.0000 for a fixed solution's standard deviation below 0.05 mm (the mosaic
    // pair's reference: line 13): read as the printed resolution, counted.
    double* sds[3] = {&sdn, &sde, &sdu};
    bool zero = false;
    for (double* s : sds) {
      if (*s == 0.0) {
        *s = kPrintedResolution;
        zero = true;
      }
    }
    if (zero && zeros++ == 0) first_zero = line;
    if (!fixes.empty() && !(f.t > fixes.back().t)) {
      throw DataError(path, line, "time does not increase");
    }
    f.p_e = ecefFromGeodetic({lat * kDegToRad, lon * kDegToRad, h});
    // RTKLIB writes covariances as signed square roots; order E, N, U.
    const auto cov = [](double s) { return s < 0.0 ? -s * s : s * s; };
    f.cov_enu << sde * sde, cov(sdne), cov(sdeu), cov(sdne), sdn * sdn, cov(sdun), cov(sdeu),
        cov(sdun), sdu * sdu;
    if (Eigen::LLT<Eigen::Matrix3d>(f.cov_enu).info() != Eigen::Success) {
      // RTKLIB's fixed solutions print correlations past +-1 (sdn 0.0042, sde 0.0016, sdne
      // -0.0029 on a real car drive: -1.25), and a near-singular covariance written to 0.1 mm
      // rounds to them: repaired, counted, not refused.
      f.cov_enu = nearestPositiveDefinite(f.cov_enu);
      if (repaired++ == 0) first_repaired = line;
    }
    f.quality = static_cast<int>(q);
    f.satellites = static_cast<int>(ns);
    fixes.push_back(f);
  }
  if (zeros > 0 && warnings) {
    warnings->push_back(path + ":" + std::to_string(first_zero) + ": " + std::to_string(zeros) +
                        " rows with a standard deviation printed as 0 read as 0.1 mm, the "
                        "printed resolution (first here)");
  }
  if (repaired > 0 && warnings) {
    warnings->push_back(path + ":" + std::to_string(first_repaired) + ": " +
                        std::to_string(repaired) +
                        " rows with a covariance that is not positive definite (correlations "
                        "beyond +-1) read as the nearest positive definite one with the same "
                        "standard deviations (first here)");
  }
  return fixes;
}

}  // namespace giocal
