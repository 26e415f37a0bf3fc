// The giocal command: parses the sub-command and its options and calls the libraries.
#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>

#include "apps/calibrate_command.h"
#include "apps/check_command.h"
#include "apps/command_line.h"
#include "apps/compare_command.h"
#include "apps/dataset_commands.h"
#include "apps/deadreckon_command.h"
#include "apps/gnss_options.h"
#include "apps/interrupt_watch.h"
#include "apps/observability_command.h"
#include "apps/report_command.h"
#include "apps/rtk_command.h"
#include "apps/validate_command.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/rtk_job.h"
#include "common/io/data_error.h"
#include "common/io/sensor_logs.h"
#include "common/io/tum_trajectory.h"

namespace po = boost::program_options;
using giocal::addGnssOptions;
using giocal::lcPositions;
using giocal::singleReceiver;

namespace {

const char* kUsage =
    "giocal: online IMU-odometer calibration from raw GNSS\n"
    "usage:\n"
    "  giocal check     --data <dir>\n"
    "  giocal simulate  --config <yaml> --out <dir> [--seed <n>] [--no-base]\n"
    "  giocal simulate  --config <yaml> --trajectory <file.pos> --rover <obs> [--base <obs>]\n"
    "                   --nav <nav>... --out <dir> [--seed <n>]\n"
    "  giocal simulate  --config <yaml> --static-rover <obs> --rover-pos x,y,z [--base <obs>\n"
    "                   [--base-pos x,y,z]] --nav <nav>... --out <dir> [--seed <n>]\n"
    "  giocal rtk       --rover <obs> --base <obs> --nav <nav> [--nav <nav>...] [--base-pos "
    "x,y,z]\n"
    "                   [--config <yaml>] --out <file.pos> [--overwrite]\n"
    "  giocal calibrate --data <dir> [--estimator ekf|fgo] [--gnss tc|single|lc --pos <file.pos>]\n"
    "                   [--config <yaml>] --out <dir> [--overwrite] [--quiet]\n"
    "  giocal compare   --data <dir> [--gnss tc|single|lc --pos <file.pos>] [--config <yaml>] "
    "[--out "
    "<dir>]\n"
    "                   [--overwrite] [--quiet]\n"
    "  giocal deadreckon --data <dir> --calibration <run/summary.json|calibration.csv@s|truth|"
    "guess>\n"
    "                   [--start <s>] [--duration <s>] [--reference <trajectory.csv|file.pos>] "
    "[--config <yaml>]\n"
    "                   [--gnss tc|single|lc --pos <file.pos>]\n"
    "                   --out <dir> [--overwrite] [--quiet]\n"
    "  giocal import    --ubx <file.ubx> --out <dir> [--overwrite] [--quiet]\n"
    "  giocal import    --bag <file.bag> [--imu-topic t] [--odom-topic t] [--fix-topic t]\n"
    "                   --out <dir> [--overwrite] [--quiet]\n"
    "  giocal import    --i2nav-imu <imu.txt> [--i2nav-pos <gnss.pos>] [--i2nav-nav <truth.nav>]\n"
    "                   [--gps-week n] [--lever-arm x,y,z] --out <dir> [--overwrite]\n"
    "  giocal export    --trajectory <trajectory.csv> --tum <file.txt> [--origin x,y,z] "
    "[--overwrite]\n"
    "  giocal report    --run <dir | box.csv> [--data <dataset>] --out <dir> [--overwrite]\n"
    "  giocal observability --data <dir> [--calibration truth|guess] [--pos <file.pos>]\n"
    "                   [--gnss tc|single] [--window <s>] [--out <dir>]\n"
    "  giocal validate  --data <dir> --run <calibrate dir> [--outage <s>] [--windows <n>]\n"
    "                   [--gnss tc|single|lc --pos <file.pos>] [--config <yaml>] --out <dir> "
    "[--overwrite]\n"
    "  giocal <command> --help     the command's options, their defaults and an example\n"
    "  giocal --version\n"
    "  (calibrate, compare, deadreckon and import show their progress on standard error when it is "
    "a\n"
    "  terminal; --quiet turns that off)\n";

const char* const kCommands[] = {"check",   "simulate",      "rtk",     "calibrate",
                                 "compare", "deadreckon",    "import",  "export",
                                 "report",  "observability", "validate"};

/// The options every command that writes a run's outputs takes: config, out, overwrite, quiet.
void addRunOutputOptions(po::options_description& opts, bool out_required) {
  opts.add_options()("config", po::value<std::string>()->default_value(""), "YAML configuration")(
      "out",
      out_required ? po::value<std::string>()->required()
                   : po::value<std::string>()->default_value(""),
      "output folder")("overwrite", "replace existing outputs in --out")("quiet",
                                                                         "no progress line");
}

/// The options addRunOutputOptions() declared, into a job with config, out, overwrite, quiet.
template <class Job>
void readRunOutputOptions(const po::variables_map& vm, Job& job) {
  job.config = vm["config"].as<std::string>();
  job.out = vm["out"].as<std::string>();
  job.overwrite = vm.count("overwrite") != 0;
  job.quiet = vm.count("quiet") != 0;
}

int runCheckCommand(int argc, char** argv) {
  po::options_description opts("giocal check");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder");
  const po::variables_map vm =
      giocal::parseCommand(argc, argv, opts,
                           "giocal check: reads a dataset folder and says whether it can be "
                           "calibrated (or which condition makes it unusable)",
                           "giocal check --data data/sim/paper");
  giocal::DatasetFolder data = giocal::openDatasetFolder(vm["data"].as<std::string>());
  giocal::runCheck(data, std::cout);
  std::cout << "ok\n";
  return 0;
}

int runCalibrateCommand(int argc, char** argv) {
  po::options_description opts("giocal calibrate");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder")(
      "estimator", po::value<std::string>()->default_value("ekf"), "ekf or fgo")(
      "prior", po::value<std::string>()->default_value(""),
      "an earlier drive's summary.json or state file to start from (same robot)")(
      "state-out", po::value<std::string>()->default_value(""),
      "keep the calibration and its covariance in this file (atomically, with a checksum) every "
      "--state-every seconds of data and at the end: a power cut loses at most that much")(
      "state-every", po::value<double>()->default_value(60.0),
      "seconds of data between writes of --state-out")(
      "no-validate", po::bool_switch(),
      "skip the check at the end (validate's GNSS outage windows, dead-reckoned with the "
      "calibration and with the guess)");
  addGnssOptions(opts);
  addRunOutputOptions(opts, true);
  const po::variables_map vm = giocal::parseCommand(
      argc, argv, opts,
      "giocal calibrate: calibrates s_v, s_w, p_b_m and q_b_m from a dataset, with the EKF or the "
      "factor graph",
      "giocal calibrate --data /tmp/paper --estimator fgo --out /tmp/paper-fgo");
  giocal::CalibrateJob job;
  job.data = vm["data"].as<std::string>();
  job.estimator = vm["estimator"].as<std::string>();
  job.prior = vm["prior"].as<std::string>();
  job.state_out = vm["state-out"].as<std::string>();
  job.state_every_s = vm["state-every"].as<double>();
  job.validate = !vm["no-validate"].as<bool>();
  if (!(job.state_every_s > 0.0)) throw po::error("--state-every must be positive");
  job.positions = lcPositions(vm);
  job.single = singleReceiver(vm);
  readRunOutputOptions(vm, job);
  const giocal::InterruptWatch interrupts;
  job.stop = interrupts.stop();
  const giocal::CalibrationRun run = giocal::runCalibrate(job, std::cout);
  // 3: the run finished but does not believe its answer (status "suspect: ..."; docs/commands.md).
  return run.status.rfind("suspect", 0) == 0 ? 3 : 0;
}

int runCompareCommand(int argc, char** argv) {
  po::options_description opts("giocal compare");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder");
  addGnssOptions(opts);
  addRunOutputOptions(opts, false);
  const po::variables_map vm =
      giocal::parseCommand(argc, argv, opts,
                           "giocal compare: calibrates the same dataset with both estimators and "
                           "prints them side by side",
                           "giocal compare --data /tmp/paper --out /tmp/paper-compare");
  giocal::CompareJob job;
  job.data = vm["data"].as<std::string>();
  job.positions = lcPositions(vm);
  job.single = singleReceiver(vm);
  readRunOutputOptions(vm, job);
  const giocal::InterruptWatch interrupts;
  job.stop = interrupts.stop();
  return giocal::runCompare(job, std::cout) ? 3 : 0;  // 3: a run does not believe its answer
}

int runValidateCommand(int argc, char** argv) {
  po::options_description opts("giocal validate");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder")(
      "run", po::value<std::string>()->required(), "the calibrate output folder to check")(
      "outage", po::value<double>()->default_value(60.0), "each window's GNSS outage [s]")(
      "windows", po::value<int>()->default_value(5), "windows spread over the drive");
  addGnssOptions(opts);
  addRunOutputOptions(opts, true);
  const po::variables_map vm = giocal::parseCommand(
      argc, argv, opts,
      "giocal validate: checks a calibration on the drive without a truth: GNSS outages "
      "dead-reckoned with it and with the initial guess, against the GNSS solution",
      "giocal validate --data /tmp/field --run /tmp/field-ekf --out /tmp/field-validate");
  giocal::ValidateJob job;
  job.data = vm["data"].as<std::string>();
  job.run = vm["run"].as<std::string>();
  job.outage_s = vm["outage"].as<double>();
  job.windows = vm["windows"].as<int>();
  job.positions = lcPositions(vm);
  job.single = singleReceiver(vm);
  readRunOutputOptions(vm, job);
  const giocal::InterruptWatch interrupts;
  job.stop = interrupts.stop();
  giocal::runValidate(job, std::cout);
  return 0;
}

int runReportCommand(int argc, char** argv) {
  po::options_description opts("giocal report");
  opts.add_options()(
      "run", po::value<std::string>()->required(),
      "a calibrate, compare, deadreckon or validate output folder, or a --box-csv file")(
      "data", po::value<std::string>()->default_value(""), "the dataset (for its truth)")(
      "out", po::value<std::string>()->required(), "output folder")(
      "overwrite", "replace an earlier report in --out");
  const po::variables_map vm = giocal::parseCommand(
      argc, argv, opts,
      "giocal report: an HTML page with figures from a calibrate, compare, deadreckon or validate "
      "output "
      "folder",
      "giocal report --run /tmp/paper-compare --data /tmp/paper --out /tmp/paper-report");
  giocal::runReport({vm["run"].as<std::string>(), vm["data"].as<std::string>(),
                     vm["out"].as<std::string>(), vm.count("overwrite") > 0},
                    std::cout);
  return 0;
}

int runExportCommand(int argc, char** argv) {
  po::options_description opts("giocal export");
  opts.add_options()("trajectory", po::value<std::string>()->required(),
                     "trajectory.csv of calibrate or deadreckon, or a dataset's truth.csv")(
      "tum", po::value<std::string>()->required(), "TUM text file to write")(
      "origin", po::value<std::string>()->default_value(""),
      "ECEF x,y,z of the ENU origin [m] (default: the first position)")(
      "overwrite", "replace --tum if it exists");
  const po::variables_map vm = giocal::parseCommand(
      argc, argv, opts,
      "giocal export: a trajectory.csv (or truth.csv) as a TUM text trajectory for evo or ov_eval",
      "giocal export --trajectory /tmp/paper-fgo/trajectory.csv --tum /tmp/paper-fgo.tum");
  const std::string out = vm["tum"].as<std::string>();
  if (std::filesystem::exists(out) && !vm.count("overwrite")) {
    throw std::runtime_error(out + " exists; give --overwrite to replace it");
  }
  const auto samples = giocal::readTruthCsv(vm["trajectory"].as<std::string>());
  if (samples.empty()) throw std::runtime_error(vm["trajectory"].as<std::string>() + ": no rows");
  const std::string origin = vm["origin"].as<std::string>();
  const Eigen::Vector3d origin_e =
      origin.empty()
          ? giocal::ecefFromGeodetic({samples.front().lat_deg * M_PI / 180.0,
                                      samples.front().lon_deg * M_PI / 180.0, samples.front().h})
          : giocal::parseBasePosition(origin);
  giocal::writeTumTrajectory(out, samples, origin_e);
  std::cout << "giocal export: " << samples.size() << " poses -> " << out << "\n";
  return 0;
}

int runDeadReckonCommand(int argc, char** argv) {
  po::options_description opts("giocal deadreckon");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder")(
      "calibration", po::value<std::string>()->required(),
      "run/summary.json, calibration.csv@<s>, truth or guess")(
      "start", po::value<double>()->default_value(100.0),
      "outage start, s after the first rover epoch")(
      "duration", po::value<double>()->default_value(1000.0), "outage length [s]")(
      "reference", po::value<std::string>()->default_value(""),
      "reference trajectory.csv, or a .pos file (default: the dataset's truth.csv)");
  addGnssOptions(opts);
  addRunOutputOptions(opts, true);
  const po::variables_map vm =
      giocal::parseCommand(argc, argv, opts,
                           "giocal deadreckon: IMU + odometer dead reckoning through a GNSS outage "
                           "with a given calibration, against a reference",
                           "giocal deadreckon --data /tmp/field --calibration "
                           "/tmp/field-ekf/summary.json --start 100 --duration 1000 --out /tmp/dr");
  giocal::DeadReckonJob job;
  job.data = vm["data"].as<std::string>();
  job.calibration = vm["calibration"].as<std::string>();
  job.start_s = vm["start"].as<double>();
  job.duration_s = vm["duration"].as<double>();
  job.reference = vm["reference"].as<std::string>();
  job.positions = lcPositions(vm);
  job.single = singleReceiver(vm);
  readRunOutputOptions(vm, job);
  const giocal::InterruptWatch interrupts;
  job.stop = interrupts.stop();
  giocal::runDeadReckon(job, std::cout);
  return 0;
}

int runObservabilityCommand(int argc, char** argv) {
  po::options_description opts("giocal observability");
  opts.add_options()("data", po::value<std::string>()->required(), "dataset folder")(
      "calibration", po::value<std::string>()->default_value(""),
      "truth or guess: where the models are linearized (default: truth when the dataset has it)")(
      "pos", po::value<std::string>()->default_value(""),
      "an RTK solution of the drive, for a dataset without truth.csv")(
      "gnss", po::value<std::string>()->default_value("tc"),
      "tc: a rover and a base (fixed DD phase); single: one receiver, no base (time-differenced "
      "phase, Doppler, single point positions; also when dataset.yaml names no base)")(
      "window", po::value<double>()->default_value(30.0), "analysis window [s]")(
      "position-sigma", po::value<double>()->default_value(0.0),
      "sigma per axis of the antenna positions made from truth.csv [m]; 0: each epoch's from "
      "its fixed DD carrier phase (satellites, mask and noise of the configuration)")(
      "config", po::value<std::string>()->default_value(""), "YAML configuration")(
      "out", po::value<std::string>()->default_value(""), "folder for observability.json")(
      "overwrite", "replace observability.json in --out");
  const po::variables_map vm = giocal::parseCommand(
      argc, argv, opts,
      "giocal observability: before calibrating, what a drive can calibrate: the expected sigma "
      "of each parameter per window and in total, weak directions, and advice on the motion",
      "giocal observability --data /tmp/paper --window 30");
  giocal::ObservabilityCommandJob job;
  job.data = vm["data"].as<std::string>();
  job.calibration = vm["calibration"].as<std::string>();
  job.positions = vm["pos"].as<std::string>();
  job.gnss = vm["gnss"].as<std::string>();
  job.window_s = vm["window"].as<double>();
  job.position_sigma_m = vm["position-sigma"].as<double>();
  job.config = vm["config"].as<std::string>();
  job.out = vm["out"].as<std::string>();
  job.overwrite = vm.count("overwrite") != 0;
  giocal::runObservability(job, std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  if (std::string(argv[1]) == "--version") {
    std::cout << "giocal " << GIOCAL_VERSION << "\n";
    return 0;
  }
  const std::string command = argv[1];
  try {
    if (command == "check") return runCheckCommand(argc - 1, argv + 1);
    if (command == "simulate") return giocal::runSimulateCommand(argc - 1, argv + 1);
    if (command == "rtk") return giocal::runRtkCommand(argc - 1, argv + 1);
    if (command == "calibrate") return runCalibrateCommand(argc - 1, argv + 1);
    if (command == "compare") return runCompareCommand(argc - 1, argv + 1);
    if (command == "deadreckon") return runDeadReckonCommand(argc - 1, argv + 1);
    if (command == "import") return giocal::runImportCommand(argc - 1, argv + 1);
    if (command == "export") return runExportCommand(argc - 1, argv + 1);
    if (command == "report") return runReportCommand(argc - 1, argv + 1);
    if (command == "observability") return runObservabilityCommand(argc - 1, argv + 1);
    if (command == "validate") return runValidateCommand(argc - 1, argv + 1);
    const std::string near =
        giocal::likelyMeant(command, {std::begin(kCommands), std::end(kCommands)});
    std::cerr << "giocal: unknown command '" << command << "'"
              << (near.empty() ? "" : "; did you mean '" + near + "'?") << "\n"
              << kUsage;
    return 2;
  } catch (const giocal::HelpShown&) {
    return 0;
  } catch (const giocal::Interrupted& e) {
    std::cerr << "giocal " << command << ": " << e.what()
              << "; nothing written (earlier outputs, if any, are unchanged)\n";
    return 128 + e.signal();
  } catch (const giocal::DataError& e) {
    std::cerr << "giocal " << command << ": " << e.what() << "\n";
    return 1;
  } catch (const po::error& e) {
    std::cerr << "giocal " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "giocal " << command << ": " << e.what() << "\n";
    return 1;
  }
}
