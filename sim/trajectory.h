// Trajectory: the exact kinematics of the vehicle frame m along a MotionProfile over sinusoidal
// terrain, in the local ENU frame n. m's forward axis follows the 3D path (no lateral or vertical
// velocity: differential-drive kinematics); it pitches with the slope and never rolls.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/motion_profile.h"

namespace giocal::sim {

struct Terrain {
  double amplitude = 0.0;     // height h(s) = amplitude * sin(2 pi s / wavelength) [m]
  double wavelength = 100.0;  // s: horizontal distance travelled [m]
};

/// The state of m at one instant.
struct VehicleKinematics {
  double t = 0.0;
  Eigen::Matrix3d R_n_m;
  Eigen::Vector3d p_n_m, v_n_m, a_n_m;  // position, velocity, acceleration in n
  Eigen::Vector3d w_m, alpha_m;         // angular rate of m relative to n, in m, and its derivative
  double speed = 0.0;                   // forward speed along the path (what the wheels measure)
};

/// A vehicle path: the kinematics of m at each time since the path's start.
class VehiclePath {
 public:
  virtual ~VehiclePath() = default;
  virtual double duration() const = 0;
  virtual VehicleKinematics at(double t) const = 0;
};

/// Heading psi, pitch theta and forward speed with their derivatives at one instant.
struct PlanarMotion {
  double v = 0.0, v_dot = 0.0;
  double psi = 0.0, psi_dot = 0.0, psi_ddot = 0.0;
  double th = 0.0, th_dot = 0.0, th_ddot = 0.0;
};

/// The kinematics of m at position p_n_m moving as `m` says: R_n_m = Rz(psi) Rx(theta), the
/// velocity along m's forward axis y, no roll.
VehicleKinematics planarKinematics(double t, const Eigen::Vector3d& p_n_m, const PlanarMotion& m);

class Trajectory : public VehiclePath {
 public:
  /// initial_heading: angle of m's forward axis from north towards west (yaw of R_n_m) [rad].
  Trajectory(MotionProfile profile, Terrain terrain, const Eigen::Vector3d& p0_n,
             double initial_heading);

  double duration() const override { return profile_.duration(); }
  VehicleKinematics at(double t) const override;

 private:
  struct Node {
    double psi, s, x, y;  // heading, path length, east, north
  };
  Node integrate(Node n, double t0, double t1) const;
  void terrainSlope(double s, double& h, double& dh, double& d2h, double& d3h) const;

  MotionProfile profile_;
  Terrain terrain_;
  Eigen::Vector3d p0_n_;
  double node_dt_ = 0.01;  // stored every 10 ms, RK4 in 1 ms steps in between
  std::vector<Node> nodes_;
};

}  // namespace giocal::sim
