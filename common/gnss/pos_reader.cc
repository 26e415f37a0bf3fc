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

std::vector<PositionFix> readPosFile(const std::string& path) {
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
    if (!(sdn > 0.0 && sde > 0.0 && sdu > 0.0)) {
      throw DataError(path, line, "sdn, sde and sdu must be positive");
    }
    if (!fixes.empty() && !(f.t > fixes.back().t)) {
      throw DataError(path, line, "time does not increase");
    }
    f.p_e = ecefFromGeodetic({lat * kDegToRad, lon * kDegToRad, h});
    // RTKLIB writes covariances as signed square roots; order E, N, U.
    const auto cov = [](double s) { return s < 0.0 ? -s * s : s * s; };
    f.cov_enu << sde * sde, cov(sdne), cov(sdeu), cov(sdne), sdn * sdn, cov(sdun), cov(sdeu),
        cov(sdun), sdu * sdu;
    if (Eigen::LLT<Eigen::Matrix3d>(f.cov_enu).info() != Eigen::Success) {
      // A near-singular covariance (few satellites) written to 0.1 mm can round to correlations
      // just past 1: the nearest positive definite matrix is the solution's. Beyond rounding the
      // file is wrong.
      const Eigen::Vector3d sd_enu = f.cov_enu.diagonal().cwiseSqrt();
      const Eigen::Matrix3d rho =
          sd_enu.cwiseInverse().asDiagonal() * f.cov_enu * sd_enu.cwiseInverse().asDiagonal();
      if ((rho - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1.01) {
        throw DataError(path, line, "the covariance is not positive definite");
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(f.cov_enu);
      const double floor = 1e-6 * f.cov_enu.diagonal().maxCoeff();
      f.cov_enu = eig.eigenvectors() * eig.eigenvalues().cwiseMax(floor).asDiagonal() *
                  eig.eigenvectors().transpose();
    }
    f.quality = static_cast<int>(q);
    f.satellites = static_cast<int>(ns);
    fixes.push_back(f);
  }
  return fixes;
}

}  // namespace giocal
