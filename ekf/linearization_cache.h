// LinearizationCache: the EKF's linearization storage kept per kind of model (its residual size
// and block count), so that models of different sizes taking turns do not reallocate it.
#pragma once

#include <array>
#include <cstddef>

#include "common/models/measurement_model.h"
#include "common/models/measurement_rows.h"

namespace giocal {

class LinearizationCache {
 public:
  struct Storage {
    MeasurementRows rows;
    LinearizeScratch scratch;
  };
  /// The storage last used by a model of this kind, or the least recently used one.
  Storage& forModel(const MeasurementModel& model);

 private:
  // The vehicle's models (odometer interval, NHC, ZUPT, heading) keep theirs while a GNSS
  // epoch's updates, whose sizes change from epoch to epoch, take the others in turn.
  struct Slot {
    int rows = -1;
    std::size_t blocks = 0;
    long used = 0;
    Storage storage;
  };
  std::array<Slot, 8> slots_;
  long clock_ = 0;
};

}  // namespace giocal
