#include "apps/dataset_commands.h"

#include <boost/program_options.hpp>
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/import_command.h"
#include "apps/interrupt_watch.h"
#include "apps/simulate_command.h"
#include "common/gnss/rtk_job.h"

namespace po = boost::program_options;

namespace giocal {

int runSimulateCommand(int argc, char** argv) {
  po::options_description opts("giocal simulate");
  opts.add_options()("config", po::value<std::string>()->required(), "simulator preset (YAML)")(
      "out", po::value<std::string>()->required(), "output dataset folder")(
      "seed", po::value<std::uint64_t>()->default_value(1), "random seed")(
      "no-base", po::bool_switch(),
      "a rover alone (as gnss.base: none in the preset, with its default broadcast, atmosphere "
      "and clock errors): for --gnss single")(
      "trajectory", po::value<std::string>()->default_value(""),
      "RTKLIB-style .pos of the rover antenna: real GNSS, motion sensors synthesized along it")(
      "rover", po::value<std::string>()->default_value(""), "with --trajectory: rover RINEX")(
      "base", po::value<std::string>()->default_value(""),
      "with --trajectory: base RINEX (left out: a rover alone, for --gnss single)")(
      "nav", po::value<std::vector<std::string>>()->multitoken(),
      "with --trajectory: RINEX navigation file(s)")(
      "knot-spacing", po::value<double>()->default_value(0.0),
      "with --trajectory: seconds between the fitted path's knots (0: twice the solutions')")(
      "static-rover", po::value<std::string>()->default_value(""),
      "a static receiver's RINEX: its real observations moved along the preset's drive (with "
      "--rover-pos, --nav and --base, or no base for a rover alone)")(
      "rover-pos", po::value<std::string>()->default_value(""),
      "with --static-rover: the receiver's surveyed antenna position, ECEF x,y,z [m]")(
      "base-pos", po::value<std::string>()->default_value(""),
      "with --static-rover: the base's surveyed position, ECEF x,y,z [m] (else its header's)");
  const po::variables_map vm = parseCommand(
      argc, argv, opts,
      "giocal simulate: writes a simulated dataset (IMU, odometer, rover and base RINEX, truth) "
      "from a preset",
      "giocal simulate --config config/sim/paper.yaml --out /tmp/paper --seed 7");
  const InterruptWatch interrupts;
  GivenGnss given;
  given.trajectory = vm["trajectory"].as<std::string>();
  given.rover = vm["rover"].as<std::string>();
  given.base = vm["base"].as<std::string>();
  if (vm.count("nav")) given.nav = vm["nav"].as<std::vector<std::string>>();
  given.knot_spacing = vm["knot-spacing"].as<double>();
  const std::string static_rover = vm["static-rover"].as<std::string>();
  if (!static_rover.empty()) {
    if (!given.trajectory.empty() || !given.rover.empty() || vm["no-base"].as<bool>()) {
      throw std::runtime_error(
          "--static-rover does not go with --trajectory, --rover or --no-base (leave --base out "
          "for a rover alone)");
    }
    if (vm["rover-pos"].as<std::string>().empty())
      throw std::runtime_error("--static-rover needs --rover-pos (and --nav)");
    MovedGnss moved;
    moved.rover = static_rover;
    moved.base = given.base;
    moved.nav = given.nav;
    moved.rover_pos = parseBasePosition(vm["rover-pos"].as<std::string>(), "--rover-pos");
    if (!vm["base-pos"].as<std::string>().empty())
      moved.base_pos = parseBasePosition(vm["base-pos"].as<std::string>(), "--base-pos");
    runSimulateMoved(vm["config"].as<std::string>(), moved, vm["out"].as<std::string>(),
                     vm["seed"].as<std::uint64_t>(), std::cout, interrupts.stop());
    return 0;
  }
  if (!vm["rover-pos"].as<std::string>().empty() || !vm["base-pos"].as<std::string>().empty())
    throw std::runtime_error("--rover-pos and --base-pos go with --static-rover");
  if (given.trajectory.empty()) {
    if (!given.rover.empty() || !given.base.empty() || !given.nav.empty()) {
      throw std::runtime_error("--rover, --base and --nav go with --trajectory");
    }
    runSimulate(vm["config"].as<std::string>(), vm["out"].as<std::string>(),
                vm["seed"].as<std::uint64_t>(), std::cout, interrupts.stop(),
                vm["no-base"].as<bool>());
  } else {
    if (vm["no-base"].as<bool>())
      throw std::runtime_error("--no-base does not go with --trajectory (not yet)");
    if (given.rover.empty()) {
      throw std::runtime_error(
          "--trajectory needs --rover and --nav (and --base, but for a rover alone)");
    }
    runSimulateAlong(vm["config"].as<std::string>(), given, vm["out"].as<std::string>(),
                     vm["seed"].as<std::uint64_t>(), std::cout, interrupts.stop());
  }
  return 0;
}

int runImportCommand(int argc, char** argv) {
  po::options_description opts("giocal import");
  opts.add_options()("ubx", po::value<std::string>()->default_value(""), "u-blox UBX log")(
      "bag", po::value<std::string>()->default_value(""), "ROS 1 bag, rosbag2 folder or .db3")(
      "imu-topic", po::value<std::string>()->default_value(""), "sensor_msgs/Imu topic")(
      "odom-topic", po::value<std::string>()->default_value(""),
      "nav_msgs/Odometry or geometry_msgs/TwistStamped topic")(
      "fix-topic", po::value<std::string>()->default_value(""), "sensor_msgs/NavSatFix topic")(
      "stamps", po::value<std::string>()->default_value("auto"),
      "a bag's sample times: header (the stamps), record (the bag's receive times) or auto "
      "(record times for a topic whose stamps are frozen, repeat or run far from them)")(
      "i2nav-imu", po::value<std::string>()->default_value(""),
      "i2Nav IMU text (increments, odometer speed column)")(
      "i2nav-pos", po::value<std::string>()->default_value(""), "i2Nav GNSS position file")(
      "i2nav-nav", po::value<std::string>()->default_value(""), "i2Nav reference .nav file")(
      "gps-week", po::value<int>()->default_value(-1),
      "GPS week of the i2Nav IMU's first row (default: the .nav's)")(
      "lever-arm", po::value<std::string>()->default_value(""),
      "x,y,z: GNSS antenna in the i2Nav IMU frame (forward-right-down) [m]")(
      "out", po::value<std::string>()->required(), "output folder")(
      "overwrite", "replace the outputs of an earlier import in --out")("quiet",
                                                                        "no progress line");
  const po::variables_map vm = parseCommand(
      argc, argv, opts,
      "giocal import: a ROS 1 or ROS 2 bag, a u-blox UBX log or i2Nav text logs, to a dataset "
      "folder giocal reads",
      "giocal import --bag test1.bag --out /tmp/husky");
  ImportJob job;
  job.ubx = vm["ubx"].as<std::string>();
  job.bag = vm["bag"].as<std::string>();
  job.imu_topic = vm["imu-topic"].as<std::string>();
  job.odom_topic = vm["odom-topic"].as<std::string>();
  job.fix_topic = vm["fix-topic"].as<std::string>();
  job.stamps = vm["stamps"].as<std::string>();
  job.i2nav_imu = vm["i2nav-imu"].as<std::string>();
  job.i2nav_pos = vm["i2nav-pos"].as<std::string>();
  job.i2nav_nav = vm["i2nav-nav"].as<std::string>();
  job.gps_week = vm["gps-week"].as<int>();
  job.lever_arm = vm["lever-arm"].as<std::string>();
  job.out = vm["out"].as<std::string>();
  job.overwrite = vm.count("overwrite") > 0;
  job.quiet = vm.count("quiet") > 0;
  const InterruptWatch interrupts;
  job.stop = interrupts.stop();
  runImport(job, std::cout);
  return 0;
}

}  // namespace giocal
