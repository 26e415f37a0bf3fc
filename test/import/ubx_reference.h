// The same u-blox log converted by giocal's import and, independently, by RTKLIB's convbin
// (Debian package rtklib), both written as RINEX 3.04 and read back; and their ephemerides
// compared field by field.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_nav_writer.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rinex_obs_writer.h"
#include "import/ubx_log.h"
#include "temp_dir.h"

namespace giocal::test {

struct Converted {
  ObsData obs;
  NavData nav;
};

inline Converted convbin(const test::TempDir& dir, const std::string& ubx) {
  const std::string cmd = "convbin -r ubx -v 3.04 -od -os -oi -ot -o " + dir.file("cb.obs") +
                          " -n " + dir.file("cb.nav") + " " + ubx + " > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << "convbin (Debian package rtklib) must be installed";
  return {readRinexObs(dir.file("cb.obs")), readRinexNav(dir.file("cb.nav"))};
}

inline Converted giocalImport(const test::TempDir& dir, const std::string& ubx,
                              import::UbxLog& log) {
  log = import::readUbxLog(ubx);
  RinexObsHeader h;
  h.obs_types = log.obs.header.obs_types;
  writeRinexObs(dir.file("g.obs"), h, log.obs.epochs);
  writeRinexNav(dir.file("g.nav"), log.nav, "test");
  return {readRinexObs(dir.file("g.obs")), readRinexNav(dir.file("g.nav"))};
}

// Every ephemeris of `sys` convbin decodes is giocal's too, equal in every field; returns how
// many were compared.
inline int compareEphemerides(const Converted& ours, const Converted& ref, GnssSystem sys) {
  int compared = 0;
  for (const Ephemeris& r : ref.nav.ephemerides) {
    if (r.sat.sys != sys) continue;
    const Ephemeris* o = nullptr;
    for (const Ephemeris& e : ours.nav.ephemerides) {
      if (e.sat == r.sat && e.iode == r.iode) o = &e;
    }
    EXPECT_NE(o, nullptr) << r.sat.str() << " IODE " << r.iode << " missing";
    if (!o) continue;
    ++compared;
    const double fields[][2] = {{o->toe, r.toe},
                                {o->toc, r.toc},
                                {o->af0, r.af0},
                                {o->af1, r.af1},
                                {o->af2, r.af2},
                                {o->crs, r.crs},
                                {o->crc, r.crc},
                                {o->cus, r.cus},
                                {o->cuc, r.cuc},
                                {o->cis, r.cis},
                                {o->cic, r.cic},
                                {o->delta_n, r.delta_n},
                                {o->m0, r.m0},
                                {o->e, r.e},
                                {o->sqrt_a, r.sqrt_a},
                                {o->omega0, r.omega0},
                                {o->i0, r.i0},
                                {o->omega, r.omega},
                                {o->omega_dot, r.omega_dot},
                                {o->idot, r.idot},
                                {o->tgd, r.tgd},
                                {o->tgd2, r.tgd2},
                                {o->iodc, r.iodc}};
    for (const auto& f : fields) {
      EXPECT_NEAR(f[0], f[1], 1e-11 * std::max(1.0, std::abs(f[1]))) << r.sat.str();
    }
    EXPECT_EQ(o->health, r.health) << r.sat.str();
  }
  return compared;
}

}  // namespace giocal::test
