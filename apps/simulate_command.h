// `giocal simulate --config <yaml> --out <dir> [--seed <n>]`, and with `--trajectory <file.pos>
// --rover <obs> --base <obs> --nav <nav>...`: real GNSS files with the motion sensors synthesized
// along the vehicle path of their position solution; with `--static-rover <obs> --rover-pos x,y,z`:
// a static receiver's real observations moved along the preset's drive.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "common/io/stop_request.h"

namespace giocal {

/// Refuses to write into a folder that already holds a dataset (nothing a user wrote is
/// overwritten); the dataset's files appear together, or none when `stop` is requested.
/// no_base: a rover alone, as gnss.base: none with sim::setSingleReceiverDefaults.
void runSimulate(const std::string& config, const std::string& out, std::uint64_t seed,
                 std::ostream& log, const StopRequest* stop = nullptr, bool no_base = false);

/// The given GNSS files and the preset's IMU, odometer and calibration along the path fitted to
/// `trajectory` (an RTKLIB-style .pos of the rover antenna; fixed and float solutions used).
struct GivenGnss {
  std::string trajectory, rover, base;
  std::vector<std::string> nav;
  double knot_spacing = 0.0;  // of the fitted path's splines [s]; 0: twice the solutions' interval
};
void runSimulateAlong(const std::string& config, const GivenGnss& gnss, const std::string& out,
                      std::uint64_t seed, std::ostream& log, const StopRequest* stop = nullptr);

/// A static receiver's real RINEX moved along the preset's drive (sim/moved_rover.h): the drive
/// starts at the rover file's first whole second, its IMU frame beside `rover_pos` (the receiver's
/// surveyed ECEF position), and the base and navigation files are copied as they are.
struct MovedGnss {
  std::string rover, base;
  Eigen::Vector3d rover_pos = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> base_pos;  // written as gnss.base_position_ecef
  std::vector<std::string> nav;
};
void runSimulateMoved(const std::string& config, const MovedGnss& gnss, const std::string& out,
                      std::uint64_t seed, std::ostream& log, const StopRequest* stop = nullptr);

}  // namespace giocal
