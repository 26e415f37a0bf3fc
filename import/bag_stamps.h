// Which time a bag topic's samples take: their header stamps, or the bag's record (receive) times
// where the stamps are frozen, repeat, or run far from the recording clock.
#pragma once

#include <string>
#include <vector>

namespace giocal::import {

enum class StampSource { kAuto, kHeader, kRecord };

/// "auto", "header" or "record" (giocal import --stamps); throws naming the valid ones.
StampSource stampSourceFromName(const std::string& name);

struct TopicStamps {
  std::string topic;
  std::vector<double> header, record;  // per message, in bag order
};

/// Per topic, true where its record times replace its header stamps: always (kRecord), never
/// (kHeader), or with kAuto when more than a tenth of its header stamps are not after the
/// previous one (frozen or repeating stamps), or when their median offset from the record times
/// is more than 10 s while another topic's is not (a sensor stamping on a clock of its own). Each
/// topic switched by kAuto gets a warning naming it and what was seen.
std::vector<bool> useRecordTimes(const std::vector<TopicStamps>& topics, StampSource mode,
                                 const std::string& bag, std::vector<std::string>& warnings);

}  // namespace giocal::import
