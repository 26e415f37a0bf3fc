// The elevation-dependent measurement noise model: sigma(el) = sigma_zenith * sqrt(1 + 1/sin(el)),
// as in the reference paper.
#pragma once

#include <cmath>

namespace giocal {

struct ElevationNoise {
  double sigma_zenith = 0.3;  // [m] (or [m/s] for Doppler)
  double variance(double el) const {
    const double s = std::max(std::sin(el), 0.05);  // floor at ~3 deg keeps weights finite
    return sigma_zenith * sigma_zenith * (1.0 + 1.0 / s);
  }
};

}  // namespace giocal
