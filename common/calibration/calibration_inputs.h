// CalibrationInputs: everything a calibrator reads from a dataset folder, loaded and checked once:
// dataset.yaml, the IMU and odometer logs, rover and base observations, broadcast orbits, the base
// position, and truth_calib.yaml when present.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "common/calibration/calibration_options.h"
#include "common/gnss/observation.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_nav.h"
#include "common/imu/imu_sample.h"
#include "common/io/dataset_description.h"
#include "common/io/dataset_folder.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

struct CalibrationInputs {
  DatasetDescription description;
  std::vector<ImuSample> imu;
  std::vector<OdomSample> odom;
  ObsData rover, base;
  NavData nav;
  Eigen::Vector3d base_e = Eigen::Vector3d::Zero();
  std::optional<TruthCalibration> truth;  // from truth_calib.yaml, if the folder has one
  std::vector<PositionFix> positions;     // antenna position solutions (the LC scheme)
  // With addSingleReceiverTrack: the indices of `positions` where the track began a new stretch
  // (its offset another single point position's, a jump of metres).
  std::vector<size_t> track_restarts;
  std::vector<std::string> warnings;  // recoverable damage the readers dropped

  /// Time span covered by both the IMU and the rover observations [s].
  double dataDuration() const;
};

/// Throws DataError naming the file, the line and the problem (missing file, bad rows, too few
/// samples, no base position, logs that do not overlap in time). `positions`: a .pos solution
/// file read into `positions` (the LC scheme); a dataset without raw GNSS then gets epochs
/// without observations at the solutions' times, and the first solution as its origin.
CalibrationInputs loadCalibrationInputs(const DatasetFolder& data,
                                        const std::string& positions = "");
/// The same for a folder not yet opened (opens it).
CalibrationInputs loadCalibrationInputs(const std::string& folder,
                                        const std::string& positions = "");

/// A rover alone (no base): its track of single point positions joined by time-differenced phase
/// into `in.positions` (what the initial heading is measured on), and the local origin at its
/// start. Throws when no epoch has a single point position.
void addSingleReceiverTrack(CalibrationInputs& in, const SingleReceiverOptions& options);

}  // namespace giocal
