#include "import/ublox_messages.h"

#include <cstring>
#include <initializer_list>
#include <stdexcept>

namespace giocal::import {

namespace {

bool isType(const std::string& type, const std::string& name) {
  return type == "ublox_msgs/" + name || type == "ublox_msgs/msg/" + name;
}

// The value of the first of the names the message has (ROS 1 and ROS 2 spell fields differently).
double field(const RosMessage& m, const std::string& prefix,
             std::initializer_list<const char*> names) {
  for (const char* n : names) {
    if (m.has(prefix + n)) return m.number(prefix + n);
  }
  throw std::runtime_error("ublox message without '" + prefix + *names.begin() + "'");
}

double fieldOr(const RosMessage& m, const std::string& prefix,
               std::initializer_list<const char*> names, double fallback) {
  for (const char* n : names) {
    if (m.has(prefix + n)) return m.number(prefix + n);
  }
  return fallback;
}

template <class T>
void put(std::vector<uint8_t>& p, std::size_t off, double v) {
  const T x = static_cast<T>(v);
  std::memcpy(p.data() + off, &x, sizeof(T));
}

}  // namespace

bool isUbloxRawx(const std::string& type) { return isType(type, "RxmRAWX"); }
bool isUbloxSfrbx(const std::string& type) { return isType(type, "RxmSFRBX"); }

UbxFrame rawxFrame(const RosMessage& m) {
  const std::size_t n = m.length("meas");
  UbxFrame f;
  f.cls = 0x02;
  f.id = 0x15;
  f.payload.assign(16 + 32 * n, 0);
  auto& p = f.payload;
  put<double>(p, 0, field(m, "", {"rcvTOW", "rcv_tow"}));
  put<uint16_t>(p, 8, field(m, "", {"week"}));
  put<int8_t>(p, 10, fieldOr(m, "", {"leapS", "leap_s"}, 0));
  put<uint8_t>(p, 11, static_cast<double>(n));
  put<uint8_t>(p, 12, fieldOr(m, "", {"recStat", "rec_stat"}, 0));
  put<uint8_t>(p, 13, fieldOr(m, "", {"version"}, 1));
  for (std::size_t k = 0; k < n; ++k) {
    const std::string e = "meas[" + std::to_string(k) + "].";
    const std::size_t o = 16 + 32 * k;
    put<double>(p, o, field(m, e, {"prMes", "pr_mes"}));
    put<double>(p, o + 8, field(m, e, {"cpMes", "cp_mes"}));
    put<float>(p, o + 16, field(m, e, {"doMes", "do_mes"}));
    put<uint8_t>(p, o + 20, field(m, e, {"gnssId", "gnss_id"}));
    put<uint8_t>(p, o + 21, field(m, e, {"svId", "sv_id"}));
    put<uint8_t>(p, o + 22, fieldOr(m, e, {"sigId", "sig_id", "reserved0"}, 0));
    put<uint8_t>(p, o + 23, fieldOr(m, e, {"freqId", "freq_id"}, 0));
    put<uint16_t>(p, o + 24, field(m, e, {"locktime"}));
    put<uint8_t>(p, o + 26, field(m, e, {"cno"}));
    put<uint8_t>(p, o + 27, fieldOr(m, e, {"prStdev", "pr_stdev"}, 0));
    put<uint8_t>(p, o + 28, fieldOr(m, e, {"cpStdev", "cp_stdev"}, 0));
    put<uint8_t>(p, o + 29, fieldOr(m, e, {"doStdev", "do_stdev"}, 0));
    put<uint8_t>(p, o + 30, field(m, e, {"trkStat", "trk_stat"}));
  }
  return f;
}

UbxFrame sfrbxFrame(const RosMessage& m) {
  const std::size_t n = m.length("dwrd");
  UbxFrame f;
  f.cls = 0x02;
  f.id = 0x13;
  f.payload.assign(8 + 4 * n, 0);
  auto& p = f.payload;
  put<uint8_t>(p, 0, field(m, "", {"gnssId", "gnss_id"}));
  put<uint8_t>(p, 1, field(m, "", {"svId", "sv_id"}));
  put<uint8_t>(p, 2, fieldOr(m, "", {"sigId", "sig_id", "reserved0"}, 0));
  put<uint8_t>(p, 3, fieldOr(m, "", {"freqId", "freq_id"}, 0));
  put<uint8_t>(p, 4, static_cast<double>(n));
  put<uint8_t>(p, 6, fieldOr(m, "", {"version"}, 2));
  for (std::size_t k = 0; k < n; ++k) {
    put<uint32_t>(p, 8 + 4 * k, m.number("dwrd[" + std::to_string(k) + "]"));
  }
  return f;
}

}  // namespace giocal::import
