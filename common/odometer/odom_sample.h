// One odometer sample: measured forward speed [m/s] and yaw rate [rad/s] of the vehicle frame m.
#pragma once

namespace giocal {

struct OdomSample {
  double t = 0.0;  // GPS seconds
  double v = 0.0;
  double w = 0.0;
};

}  // namespace giocal
