#include "ekf/linearization_cache.h"

namespace giocal {

LinearizationCache::Storage& LinearizationCache::forModel(const MeasurementModel& model) {
  const int rows = model.residualSize();
  const std::size_t blocks = model.blocks().size();
  Slot* pick = &slots_[0];
  for (Slot& s : slots_) {
    if (s.rows == rows && s.blocks == blocks) {
      pick = &s;
      break;
    }
    if (s.used < pick->used) pick = &s;
  }
  pick->rows = rows;
  pick->blocks = blocks;
  pick->used = ++clock_;
  return pick->storage;
}

}  // namespace giocal
