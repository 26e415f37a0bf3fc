#include "import/bag_dataset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

#include "common/geodesy/wgs84.h"
#include "common/io/text.h"
#include "common/math/median.h"
#include "common/time/gps_time.h"
#include "import/bag_sensor_noise.h"
#include "import/gnss_comm_messages.h"
#include "import/ublox_messages.h"

namespace giocal::import {

namespace {

constexpr double kUnixToGpsEpoch = 315964800.0;  // 1980-01-06 in seconds since 1970 (UTC)
constexpr double kEarliestUtcStamp = 1e9;        // 2001: smaller stamps are not wall-clock time
constexpr double kMaxStampDisagreement = 1.0;    // [s] between sensors' stamp-to-receive offsets

bool isType(const std::string& type, const std::string& pkg, const std::string& name) {
  return type == pkg + "/" + name || type == pkg + "/msg/" + name;
}

std::string topicList(const BagSource& bag) {
  std::string s;
  for (const BagTopic& t : bag.topics())
    s += (s.empty() ? "" : ", ") + t.topic + " (" + t.type + ")";
  return s.empty() ? "none" : s;
}

const BagTopic* pick(const BagSource& bag, const std::string& wanted, const std::string& what,
                     const std::vector<std::pair<std::string, std::string>>& types, bool required,
                     const std::string& flag) {
  std::vector<const BagTopic*> found;
  for (const BagTopic& t : bag.topics()) {
    const bool typed = std::any_of(types.begin(), types.end(), [&](const auto& pt) {
      return isType(t.type, pt.first, pt.second);
    });
    if (!wanted.empty() && t.topic == wanted) {
      if (!typed)
        throw std::runtime_error(bag.path() + ": topic " + wanted + " is " + t.type + ", not " +
                                 what);
      return &t;
    }
    if (wanted.empty() && typed) found.push_back(&t);
  }
  if (!wanted.empty())
    throw std::runtime_error(bag.path() + ": no topic " + wanted + " (topics: " + topicList(bag) +
                             ")");
  if (found.size() > 1) {
    std::string names;
    for (const BagTopic* t : found) names += " " + t->topic;
    throw std::runtime_error(bag.path() + ": several " + what + " topics:" + names +
                             "; choose one with " + flag);
  }
  if (found.empty() && required) {
    throw std::runtime_error(bag.path() + ": no " + what + " topic (topics: " + topicList(bag) +
                             ")");
  }
  return found.empty() ? nullptr : found.front();
}

RosSchema schemaOf(const BagSource& bag, const BagTopic& t) {
  const std::string def = t.definition.empty() ? builtinRos2Definition(t.type) : t.definition;
  if (def.empty())
    throw std::runtime_error(bag.path() + ": topic " + t.topic + " (" + t.type +
                             ") carries no message definition");
  try {
    return RosSchema(t.type, def);
  } catch (const std::exception& e) {
    throw std::runtime_error(bag.path() + ": topic " + t.topic + ": " + e.what());
  }
}

// Per topic: header stamps and receive times of the samples kept, the times chosen, their offsets
// from the receive times, the first covariances.
struct Stream {
  const BagTopic* topic = nullptr;
  RosSchema schema;
  TopicCounts* counts;
  double last = -INFINITY;
  std::vector<double> offsets;  // chosen time - receive time
  std::vector<double> covariance;
  TopicStamps stamps;  // of every sample read, in bag order
};

// The chosen times put on `samples` (header stamps or record times), those not after the
// previous one dropped and counted, the offsets and gaps kept for the checks that follow.
template <class T>
void applyTimes(std::vector<T>& samples, Stream& s, bool record) {
  std::vector<T> kept;
  kept.reserve(samples.size());
  for (size_t k = 0; k < samples.size(); ++k) {
    const double received = s.stamps.record[k];
    const double t = record ? received : s.stamps.header[k];
    if (t <= s.last) {
      ++s.counts->out_of_order;
      continue;
    }
    if (std::isfinite(s.last))
      s.counts->largest_gap_s = std::max(s.counts->largest_gap_s, t - s.last);
    s.last = t;
    s.offsets.push_back(t - received);
    samples[k].t = t;
    kept.push_back(samples[k]);
  }
  samples.swap(kept);
  s.counts->record_times = record;
}

void finishBagDataset(BagDataset& out, std::map<std::string, Stream>& streams, const BagSource& bag,
                      StampSource mode) {
  std::vector<TopicStamps> stamps;
  std::vector<Stream*> order;
  for (auto& [name, s] : streams) {
    stamps.push_back(s.stamps);
    order.push_back(&s);
  }
  const std::vector<bool> record = useRecordTimes(stamps, mode, bag.path(), out.warnings);
  for (size_t i = 0; i < order.size(); ++i) {
    Stream& s = *order[i];
    if (s.counts == &out.imu_counts) applyTimes(out.imu, s, record[i]);
    if (s.counts == &out.odom_counts) applyTimes(out.odom, s, record[i]);
    if (s.counts == &out.fix_counts) applyTimes(out.fixes, s, record[i]);
  }
  // One time base: wall-clock (UTC) stamps on every topic, or on none.
  std::string utc, other;
  for (const auto& [name, s] : streams) {
    if (s.offsets.empty()) continue;
    (s.last >= kEarliestUtcStamp ? utc : other) += " " + name;
  }
  if (!utc.empty() && !other.empty()) {
    throw std::runtime_error(bag.path() + ": mixed time bases: stamps of" + utc +
                             " are wall-clock time, those of" + other + " are not");
  }
  out.utc_stamps = other.empty();
  // Stamps that disagree with the recording clock differently per sensor.
  double lo = INFINITY, hi = -INFINITY;
  std::string offsets;
  for (const auto& [name, s] : streams) {
    if (s.offsets.empty()) continue;
    const double m = median(s.offsets);
    lo = std::min(lo, m);
    hi = std::max(hi, m);
    offsets += " " + name + " " + fixedText(m, 3) + " s;";
  }
  if (hi - lo > kMaxStampDisagreement) {
    out.warnings.push_back(bag.path() +
                           ": header stamps minus recording times differ by more than " +
                           fixedText(kMaxStampDisagreement, 0) + " s between sensors:" + offsets +
                           " one sensor's clock or stamping is off by about the difference");
  }
  for (const auto& [name, s] : streams) {
    const TopicCounts& c = *s.counts;
    if (c.out_of_order > 0)
      out.warnings.push_back(bag.path() + ": topic " + name + ": " +
                             std::to_string(c.out_of_order) +
                             " messages with a stamp not after the previous one dropped");
    if (c.non_finite > 0)
      out.warnings.push_back(bag.path() + ": topic " + name + ": " + std::to_string(c.non_finite) +
                             " messages with NaN or infinite values dropped");
    if (c.no_fix > 0)
      out.warnings.push_back(bag.path() + ": topic " + name + ": " + std::to_string(c.no_fix) +
                             " fixes with status NO_FIX dropped");
    if (c.largest_gap_s > 1.0)
      out.warnings.push_back(bag.path() + ": topic " + name + ": a gap of " +
                             fixedText(c.largest_gap_s, 2) + " s between messages");
  }
  if (out.imu.size() < 2 || out.odom.size() < 2) {
    throw std::runtime_error(bag.path() + ": fewer than 2 usable IMU or odometry messages");
  }
  Stream& imu_stream = streams.at(out.imu_counts.topic);
  convertAccelUnits(out, imu_stream.covariance, bag.path());
  setSensorNoise(out, imu_stream.covariance, streams.at(out.odom_counts.topic).covariance);
  if (!out.utc_stamps) {
    out.warnings.push_back(bag.path() + ": stamps are not wall-clock time (the first is " +
                           fixedText(out.imu.front().t, 3) +
                           " s): kept as they are, so GNSS cannot be aligned");
    return;
  }
  // ROS time is UTC since 1970; giocal's is GPS time since 1980.
  out.leap_seconds = leapSecondsAtUtc(out.imu.front().t - kUnixToGpsEpoch);
  for (auto& x : out.imu) x.t = gpsFromUtcSeconds(x.t - kUnixToGpsEpoch);
  for (auto& x : out.odom) x.t = gpsFromUtcSeconds(x.t - kUnixToGpsEpoch);
  for (auto& x : out.fixes) x.t = gpsFromUtcSeconds(x.t - kUnixToGpsEpoch);
}

}  // namespace

BagDataset readBagDataset(const BagSource& bag, const BagTopics& topics,
                          const std::function<void(double)>& progress) {
  BagDataset out;
  const BagTopic* imu =
      pick(bag, topics.imu, "sensor_msgs/Imu", {{"sensor_msgs", "Imu"}}, true, "--imu-topic");
  const BagTopic* odom =
      pick(bag, topics.odom, "nav_msgs/Odometry or geometry_msgs/TwistStamped",
           {{"nav_msgs", "Odometry"}, {"geometry_msgs", "TwistStamped"}}, true, "--odom-topic");
  const BagTopic* fix = pick(bag, topics.fix, "sensor_msgs/NavSatFix",
                             {{"sensor_msgs", "NavSatFix"}}, false, "--fix-topic");
  std::map<std::string, Stream> streams;
  auto add = [&](const BagTopic* t, TopicCounts& c) {
    if (!t) return;
    c.topic = t->topic;
    c.type = t->type;
    streams.emplace(t->topic,
                    Stream{t, schemaOf(bag, *t), &c, -INFINITY, {}, {}, {t->topic, {}, {}}});
  };
  add(imu, out.imu_counts);
  add(odom, out.odom_counts);
  add(fix, out.fix_counts);
  const bool twist_stamped = isType(odom->type, "geometry_msgs", "TwistStamped");
  std::set<std::string> names;
  for (const auto& [name, s] : streams) names.insert(name);
  // Raw GNSS: ublox_msgs and gnss_comm messages carry their own GPS time; they are decoded in bag
  // order. A bag holds one of the two conventions.
  std::map<std::string, RosSchema> raw;
  for (const BagTopic& t : bag.topics()) {
    const bool ublox = isUbloxRawx(t.type) || isUbloxSfrbx(t.type);
    const bool gnss_comm = isGnssCommMeas(t.type) || isGnssCommEphem(t.type);
    if (!ublox && !gnss_comm) continue;
    const std::string source = ublox ? "ublox_msgs" : "gnss_comm";
    if (!out.raw_gnss_source.empty() && out.raw_gnss_source != source)
      throw std::runtime_error(bag.path() +
                               ": raw GNSS both as ublox_msgs and as gnss_comm "
                               "messages; giocal reads one receiver");
    out.raw_gnss_source = source;
    std::string& slot = isUbloxRawx(t.type) || isGnssCommMeas(t.type) ? out.raw_observation_topic
                                                                      : out.raw_ephemeris_topic;
    if (!slot.empty())
      throw std::runtime_error(bag.path() + ": several " + t.type + " topics: " + slot + " " +
                               t.topic);
    slot = t.topic;
    raw.emplace(t.topic, schemaOf(bag, t));
    names.insert(t.topic);
  }
  UbxDecoder ubx(bag.path());
  GnssCommDecoder gnss_comm(bag.path());
  long long raw_messages = 0;

  // One decoded message of an IMU, odometry or fix topic into the logs.
  auto readSample = [&](Stream& s, const RosMessage& m, double received) {
    const double stamp = m.time("header.stamp");
    if (!std::isfinite(stamp)) {
      ++s.counts->out_of_order;
      return;
    }
    // Times are chosen and ordered once all are read (applyTimes); each kept sample's stamps:
    const auto keep = [&] {
      s.stamps.header.push_back(stamp);
      s.stamps.record.push_back(received);
    };
    if (s.topic == imu) {
      ImuSample x;
      x.t = stamp;
      x.gyro = {m.number("angular_velocity.x"), m.number("angular_velocity.y"),
                m.number("angular_velocity.z")};
      x.acc = {m.number("linear_acceleration.x"), m.number("linear_acceleration.y"),
               m.number("linear_acceleration.z")};
      if (!x.gyro.allFinite() || !x.acc.allFinite()) {
        ++s.counts->non_finite;
        return;
      }
      if (s.covariance.empty()) {
        s.covariance = {m.number("angular_velocity_covariance[0]"),
                        m.number("angular_velocity_covariance[4]"),
                        m.number("angular_velocity_covariance[8]"),
                        m.number("linear_acceleration_covariance[0]"),
                        m.number("linear_acceleration_covariance[4]"),
                        m.number("linear_acceleration_covariance[8]")};
      }
      out.imu.push_back(x);
      keep();
    } else if (s.topic == odom) {
      const std::string twist = twist_stamped ? "twist" : "twist.twist";
      OdomSample x{stamp, m.number(twist + ".linear.x"), m.number(twist + ".angular.z")};
      if (!std::isfinite(x.v) || !std::isfinite(x.w)) {
        ++s.counts->non_finite;
        return;
      }
      if (s.covariance.empty() && !twist_stamped) {
        s.covariance = {m.number("twist.covariance[0]"), m.number("twist.covariance[35]")};
      }
      out.odom.push_back(x);
      keep();
    } else {
      if (m.number("status.status") < 0) {
        ++s.counts->no_fix;
        return;
      }
      const double lat = m.number("latitude"), lon = m.number("longitude");
      if (!(std::abs(lat) <= 90.0 && std::abs(lon) <= 180.0)) {
        ++s.counts->non_finite;  // not a position on the Earth
        return;
      }
      Geodetic g{lat * M_PI / 180.0, lon * M_PI / 180.0, m.number("altitude")};
      Eigen::Matrix3d cov_enu;
      for (int k = 0; k < 9; ++k)
        cov_enu(k / 3, k % 3) = m.number("position_covariance[" + std::to_string(k) + "]");
      if (!std::isfinite(g.lat + g.lon + g.h) || !cov_enu.allFinite()) {
        ++s.counts->non_finite;
        return;
      }
      if (m.number("position_covariance_type") == 0 || cov_enu.diagonal().minCoeff() <= 0.0) {
        cov_enu = Eigen::Vector3d(25.0, 25.0, 100.0).asDiagonal();  // unknown: a single-point fix
      }
      RtkSolution f;
      f.t = stamp;
      const int status = static_cast<int>(m.number("status.status"));
      f.quality = status == 2 ? 4 : status == 1 ? 3 : 5;
      f.p_e = ecefFromGeodetic(g);
      const Eigen::Matrix3d R_e_n = rotationEcefFromEnu(g.lat, g.lon);
      f.cov_e = R_e_n * cov_enu * R_e_n.transpose();
      out.fixes.push_back(f);
      keep();
    }
  };
  long long total = 0, visited = 0;
  for (const BagTopic& t : bag.topics()) {
    if (names.count(t.topic)) total += t.messages;
  }
  bag.read(names, [&](const BagTopic& t, double received, const uint8_t* data, std::size_t size) {
    if (progress && total > 0 && ++visited % 1000 == 0) {
      progress(static_cast<double>(visited) / static_cast<double>(total));
    }
    if (raw.count(t.topic)) {
      const std::string where = "topic " + t.topic + ", message " + std::to_string(++raw_messages);
      try {
        const RosMessage m = RosMessage::decode(raw.at(t.topic), bag.encoding(), data, size);
        if (isUbloxRawx(t.type)) ubx.add(rawxFrame(m), where);
        if (isUbloxSfrbx(t.type)) ubx.add(sfrbxFrame(m), where);
        if (isGnssCommMeas(t.type)) gnss_comm.addMeasurements(m, where);
        if (isGnssCommEphem(t.type)) gnss_comm.addEphemeris(m, where);
      } catch (const std::exception& e) {
        throw std::runtime_error(bag.path() + ": " + where + ": " + e.what());
      }
      return;
    }
    Stream& s = streams.at(t.topic);
    try {
      readSample(s, RosMessage::decode(s.schema, bag.encoding(), data, size), received);
    } catch (const std::exception& e) {
      throw std::runtime_error(bag.path() + ": topic " + t.topic + ", message " +
                               std::to_string(s.counts->read + 1) + ": " + e.what());
    }
    ++s.counts->read;
  });
  if (out.raw_observation_topic.empty() && !out.raw_ephemeris_topic.empty()) {
    out.warnings.push_back(bag.path() + ": topic " + out.raw_ephemeris_topic +
                           ": ephemerides without raw observations; not written");
  }
  if (!out.raw_observation_topic.empty()) {
    out.raw_gnss = out.raw_gnss_source == "ublox_msgs" ? ubx.finish() : gnss_comm.finish();
    for (const std::string& w : out.raw_gnss->warnings) out.warnings.push_back(w);
  }
  finishBagDataset(out, streams, bag, topics.stamps);
  return out;
}

}  // namespace giocal::import
