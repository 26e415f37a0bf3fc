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

class Trajectory {
 public:
  /// initial_heading: angle of m's forward axis from north towards west (yaw of R_n_m) [rad].
  Trajectory(MotionProfile profile, Terrain terrain, const Eigen::Vector3d& p0_n,
             double initial_heading);

  double duration() const { return profile_.duration(); }
  VehicleKinematics at(double t) const;

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
