#include <gtest/gtest.h>

#include <set>

#include "common/models/state_key.h"

namespace giocal {
namespace {

const SatId kG5{GnssSystem::kGps, 5};

TEST(StateKey, EveryFieldTellsKeysApart) {
  // One variable per distinct key: a registry or window keyed on StateKey must never merge two.
  const std::vector<StateKey> keys{state::kP,
                                   state::kQ,
                                   at(state::kQ, Copy::kI),
                                   at(state::kQ, Copy::kStill),
                                   atEpoch(state::kQ, 12),
                                   atEpoch(state::kQ, 13),
                                   ambiguityKey(kG5, '1'),
                                   ambiguityKey(kG5, '2'),
                                   ambiguityKey(kG5, '1', 3),
                                   ambiguityKey(SatId{GnssSystem::kGalileo, 5}, '1'),
                                   ambiguityKey(SatId{GnssSystem::kGps, 6}, '1')};
  const std::set<StateKey> unique(keys.begin(), keys.end());
  EXPECT_EQ(unique.size(), keys.size());
  for (size_t a = 0; a < keys.size(); ++a) {
    for (size_t b = 0; b < keys.size(); ++b) {
      EXPECT_EQ(keys[a] == keys[b], a == b) << keys[a].str() << " " << keys[b].str();
      // A strict weak order: exactly one of a < b, b < a, a == b.
      EXPECT_EQ((keys[a] < keys[b]) + (keys[b] < keys[a]) + (keys[a] == keys[b]), 1);
    }
  }
}

TEST(StateKey, OrdinalsCompareAsTheKeysDo) {
  // The registry searches the ordinals of keys sorted by operator<: the two orders must agree,
  // at the fields' extremes too (negative epochs and PRNs, the top bits of each field).
  std::vector<StateKey> keys;
  for (const Quantity what : {Quantity::kPosition, Quantity::kAmbiguity, Quantity::kSppBias}) {
    for (const Copy copy : {Copy::kNow, Copy::kGnss}) {
      for (const int epoch : {-1, 0, 7, 1 << 20, -(1 << 30)}) {
        for (const SatId sat :
             {SatId{GnssSystem::kGps, 5}, SatId{GnssSystem::kBeidou, 63},
              SatId{GnssSystem::kGps, (1 << 24) + 1}, SatId{GnssSystem::kGps, -3}}) {
          for (const char band : {'\0', '1', '5'}) {
            for (const int version : {0, 1, -2, 1 << 30}) {
              keys.push_back({what, copy, epoch, sat, band, version});
            }
          }
        }
      }
    }
  }
  int pairs = 0;
  for (size_t a = 0; a < keys.size(); a += 7) {
    for (size_t b = 0; b < keys.size(); b += 5) {
      EXPECT_EQ(keys[a] < keys[b], keys[a].ordinal() < keys[b].ordinal())
          << keys[a].str() << " " << keys[b].str();
      EXPECT_EQ(keys[a] == keys[b], keys[a].ordinal() == keys[b].ordinal());
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 10000);
}

TEST(StateKey, PrintsAsTheNamesInMessages) {
  EXPECT_EQ(state::kPbm.str(), "p_b_m");
  EXPECT_EQ(at(state::kQ, Copy::kI).str(), "q_n_b@i");
  EXPECT_EQ(at(state::kQ, Copy::kOdo).str(), "q_n_b@odo");
  EXPECT_EQ(atEpoch(state::kSv, 12).str(), "s_v#12");
  EXPECT_EQ(ambiguityKey(kG5, '1').str(), "N:G05:1");
  EXPECT_EQ(ambiguityKey(kG5, '1', 3).str(), "N:G05:1#3");
}

}  // namespace
}  // namespace giocal
