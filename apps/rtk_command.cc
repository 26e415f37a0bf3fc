#include "apps/rtk_command.h"

#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/interrupt_watch.h"
#include "common/gnss/rtk_job.h"
#include "options/giocal_config.h"

namespace po = boost::program_options;

namespace giocal {

int runRtkCommand(int argc, char** argv) {
  po::options_description opts("giocal rtk");
  opts.add_options()("rover", po::value<std::string>()->required(), "rover RINEX observations")(
      "base", po::value<std::string>()->required(), "base RINEX observations")(
      "nav", po::value<std::vector<std::string>>()->required(), "RINEX navigation file(s)")(
      "base-pos", po::value<std::string>(), "base ECEF x,y,z [m]")(
      "config", po::value<std::string>(), "YAML configuration")(
      "out", po::value<std::string>()->required(), "solution file (.pos)")(
      "overwrite", "replace --out if it exists");
  const po::variables_map vm = parseCommand(
      argc, argv, opts,
      "giocal rtk: kinematic RTK positions of the rover antenna (LAMBDA ambiguity resolution) as "
      "an RTKLIB-style .pos",
      "giocal rtk --rover rover.obs --base base.obs --nav nav.rnx --out rover.pos");
  RtkJob job;
  job.rover = vm["rover"].as<std::string>();
  job.base = vm["base"].as<std::string>();
  job.nav = vm["nav"].as<std::vector<std::string>>();
  job.out = vm["out"].as<std::string>();
  if (std::filesystem::exists(job.out) && !vm.count("overwrite")) {
    throw std::runtime_error(job.out + " exists; give --overwrite to replace it");
  }
  if (vm.count("base-pos")) job.base_pos = parseBasePosition(vm["base-pos"].as<std::string>());
  if (vm.count("config")) job.options = readGiocalConfig(vm["config"].as<std::string>()).rtk;
  const InterruptWatch interrupts;
  job.stop = interrupts.stop();
  const RtkSummary s = runRtk(job);
  for (const std::string& w : s.warnings) std::cout << "  warning: " << w << "\n";
  std::cout << "giocal rtk: " << s.epochs << " epochs, " << s.fixed << " fixed ("
            << (s.epochs ? 100.0 * s.fixed / s.epochs : 0.0) << " %), " << s.floats << " float, "
            << s.single << " single; " << s.wall_s << " s for " << s.data_s << " s of data -> "
            << job.out << "\n";
  return 0;
}

}  // namespace giocal
