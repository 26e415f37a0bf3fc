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
