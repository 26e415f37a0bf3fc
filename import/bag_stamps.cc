#include "import/bag_stamps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/io/text.h"
#include "common/math/median.h"

namespace giocal::import {

namespace {

constexpr double kMaxRepeatShare = 0.1;  // header stamps not after the previous one, at most
constexpr double kFarFromRecord = 10.0;  // [s] median header stamp - record time, at most

double medianOffset(const TopicStamps& t) {
  std::vector<double> d;
  for (size_t k = 0; k < t.header.size(); ++k) d.push_back(t.header[k] - t.record[k]);
  return median(d);
}

}  // namespace

StampSource stampSourceFromName(const std::string& name) {
  if (name == "auto") return StampSource::kAuto;
  if (name == "header") return StampSource::kHeader;
  if (name == "record") return StampSource::kRecord;
  throw std::invalid_argument("--stamps must be auto, header or record, not '" + name + "'");
}

std::vector<bool> useRecordTimes(const std::vector<TopicStamps>& topics, StampSource mode,
                                 const std::string& bag, std::vector<std::string>& warnings) {
  std::vector<bool> record(topics.size(), mode == StampSource::kRecord);
  if (mode != StampSource::kAuto) return record;
  for (size_t i = 0; i < topics.size(); ++i) {
    const std::vector<double>& h = topics[i].header;
    long repeats = 0;
    for (size_t k = 1; k < h.size(); ++k) repeats += h[k] <= h[k - 1];
    if (h.size() > 1 &&
        static_cast<double>(repeats) > kMaxRepeatShare * static_cast<double>(h.size() - 1)) {
      record[i] = true;
      warnings.push_back(bag + ": topic " + topics[i].topic + ": " + std::to_string(repeats) +
                         " of " + std::to_string(h.size()) +
                         " header stamps not after the previous one (frozen or repeating): "
                         "the bag's record times used instead (--stamps header keeps them)");
    }
  }
  // A topic stamped far from the recording clock while another topic's stamps follow it (a
  // sensor on a clock of its own). All topics far from it: a bag of simulated or replayed time,
  // whose stamps are kept.
  std::vector<double> offset(topics.size(), NAN);
  std::string near;  // a topic whose header stamps follow the recording clock
  for (size_t i = 0; i < topics.size(); ++i) {
    if (record[i] || topics[i].header.empty()) continue;
    offset[i] = medianOffset(topics[i]);
    if (std::abs(offset[i]) <= kFarFromRecord && near.empty()) near = topics[i].topic;
  }
  if (near.empty()) return record;
  for (size_t i = 0; i < topics.size(); ++i) {
    if (!(std::abs(offset[i]) > kFarFromRecord)) continue;
    record[i] = true;
    warnings.push_back(bag + ": topic " + topics[i].topic + ": header stamps " +
                       fixedText(offset[i], 3) + " s from the record times, while " + near +
                       " follows them: the bag's record times used instead (--stamps header "
                       "keeps them)");
  }
  return record;
}

}  // namespace giocal::import
