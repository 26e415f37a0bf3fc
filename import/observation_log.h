// The header facts of decoded observation epochs: the signals per system and the sampling interval.
#pragma once

#include "common/gnss/observation.h"

namespace giocal::import {

/// Sets header.obs_types (per system, each signal seen as its C, L, D and S codes) and
/// header.interval (the median spacing of the epochs, to the millisecond).
void describeObservations(ObsData& obs);

}  // namespace giocal::import
