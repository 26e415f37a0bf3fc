// Double differences between a rover and a base receiver: the DD range model with its Jacobian
// with respect to the rover antenna position, and the DD observation bookkeeping (reference
// satellite per system and band, single-differenced ambiguity per satellite and band).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "common/gnss/satellite.h"

namespace giocal {

/// Satellite positions as each receiver sees them, and the base's geometric range.
struct SdGeometry {
  SatId sat;
  Eigen::Vector3d sat_at_rover_e;  // satellite at the rover's transmission time (Sagnac applied)
  double base_range = 0.0;         // geometric range from the base antenna [m]
  double el = 0.0;                 // elevation at the rover [rad]
  // Troposphere at the rover minus at the base [m]: a few centimetres per satellite when the two
  // antennas' heights differ by tens of metres (5 mm of zenith delay per 20 m), which a
  // kilometre baseline's fixed solution otherwise takes into its height.
  double tropo_sd = 0.0;
};

/// DD range (sat - ref, rover - base): geometric, plus the single differences' troposphere; and
/// its gradient with respect to the rover antenna position in ECEF (the troposphere's is left out:
/// under 1e-4 m per metre).
double ddRange(const Eigen::Vector3d& rover_e, const SdGeometry& sat, const SdGeometry& ref,
               Eigen::RowVector3d* d_rover);

/// One DD observation: (rover - base) of `sat` minus that of `ref`, on one band.
struct DdObservation {
  SatId sat, ref;
  char band = '1';
  bool phase = false;   // carrier phase (with ambiguity) or pseudo-range
  double value = 0.0;   // [m]
  double lambda = 0.0;  // wavelength [m]
  int sat_index = -1;   // indices into the SdGeometry list
  int ref_index = -1;
};

/// Predicted value of a DD observation [m]: the DD range, plus lambda (N_sat - N_ref) for phase
/// (SD ambiguities in cycles; ignored for code). d_rover: gradient for the rover antenna (ECEF).
double ddPredict(const DdObservation& o, const std::vector<SdGeometry>& geometry,
                 const Eigen::Vector3d& rover_e, double n_sat, double n_ref,
                 Eigen::RowVector3d* d_rover);

/// Reference satellite per group: the highest elevation, unless `previous` is still present and
/// above `keep_elevation` (keeping the reference avoids re-forming every DD ambiguity).
int chooseReference(const std::vector<SdGeometry>& geometry, const std::vector<int>& candidates,
                    int previous, double keep_elevation);

/// Covariance of DD rows: each row's own and its reference's undifferenced variance, the
/// reference's shared between rows of the same reference, band and kind.
Eigen::MatrixXd ddCovariance(const std::vector<DdObservation>& obs,
                             const std::vector<std::pair<double, double>>& undiff_variance);

}  // namespace giocal
