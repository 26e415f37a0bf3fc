#include "replay/measured_delay.h"

#include "common/io/sensor_logs.h"
#include "common/io/text.h"

namespace giocal {

OdometerDelay measureOdometerDelay(const DatasetFolder& data) {
  const DatasetDescription& d = data.description;
  if (!d.odom_noise.measures_yaw_rate) return {};
  OdometerDelayEstimator estimator(d.initial_calibration.mean.q_b_m.toRotationMatrix().col(2));
  ImuLogReader imu(data.path(d.imu));
  OdomLogReader odom(data.path(d.odom));
  ImuSample s;
  OdomSample o;
  bool have_o = odom.next(o);
  // In time order, as the calibrator releases them: each IMU sample, then the odometer up to it.
  while (imu.next(s)) {
    const double t = s.t + d.time_offsets.imu;
    estimator.addImu(t, s.gyro);
    for (; have_o && o.t + d.time_offsets.odometer <= t; have_o = odom.next(o))
      estimator.addOdometer(o.t + d.time_offsets.odometer, o.w);
  }
  return estimator.estimate();
}

double applyMeasuredOdometerDelay(DatasetFolder& data, const CalibrationOptions& options) {
  if (options.estimate_odometer_delay || options.apply_odometer_delay_sigma <= 0.0 ||
      options.apply_odometer_delay_min <= 0.0)
    return 0.0;
  const OdometerDelay d = measureOdometerDelay(data);
  if (!worthApplying(d, options.apply_odometer_delay_sigma, options.apply_odometer_delay_min))
    return 0.0;
  data.description.time_offsets.odometer -= d.delay_s;
  return d.delay_s;
}

std::string appliedDelayWarning(double applied, const DatasetFolder& data) {
  return "the odometer's stamps were measured " + fixedText(applied * 1e3, 0) +
         " ms late against the IMU's before calibrating; this calibration took them out "
         "(time_offsets.odometer " +
         fixedText(data.description.time_offsets.odometer, 3) +
         " in effect: set it in dataset.yaml to keep it; calibration.apply_odometer_delay_sigma: "
         "0 turns this off)";
}

}  // namespace giocal
