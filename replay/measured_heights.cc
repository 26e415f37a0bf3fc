#include "replay/measured_heights.h"

#include "common/io/sensor_logs.h"
#include "common/io/text.h"

namespace giocal {

FixHeights measureFixHeights(const DatasetFolder& data, const std::vector<PositionFix>& positions) {
  const DatasetDescription& d = data.description;
  DriveProfile drive(d.initial_calibration.mean.q_b_m.toRotationMatrix());
  ImuLogReader imu(data.path(d.imu));
  for (ImuSample s; imu.next(s);) {
    s.t += d.time_offsets.imu;
    drive.addImu(s);
  }
  OdomLogReader odom(data.path(d.odom));
  for (OdomSample o; odom.next(o);) {
    o.t += d.time_offsets.odometer;
    drive.addOdometer(o);
  }
  std::vector<PositionFix> fixes = positions;
  for (PositionFix& f : fixes) f.t += d.time_offsets.positions;
  return checkFixHeights(fixes, drive);
}

FixHeights measureFixHeights(const CalibrationInputs& in) {
  DriveProfile drive(in.description.initial_calibration.mean.q_b_m.toRotationMatrix());
  for (const ImuSample& s : in.imu) drive.addImu(s);
  for (const OdomSample& o : in.odom) drive.addOdometer(o);
  return checkFixHeights(in.positions, drive);
}

double applyFixHeights(const FixHeights& check, CalibrationOptions& options) {
  if (!options.lc.learn_heights || !options.lc.use_height || !check.decided ||
      check.scale() < kHeightScaleWorthApplying || check.spread_m < kHeightProfileResolution)
    return 0.0;
  options.lc.height_sigma_scale = check.scale();
  return check.scale();
}

std::string appliedHeightScaleWarning(const FixHeights& check) {
  return "the position solutions' heights stray " + fixedText(check.spread_m, 1) +
         " m (robust sigma) from the height the IMU's grade and the odometer give over " +
         fixedText(check.distance_m, 0) + " m of driving, against their own sigma of " +
         fixedText(check.reported_sigma_m, 1) + " m: their height sigmas were multiplied by " +
         fixedText(check.scale(), 1) +
         " for this run (calibration.lc.learn_heights: 0 turns this off; lc.use_height: 0 leaves "
         "the heights out)";
}

}  // namespace giocal
