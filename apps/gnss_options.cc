#include "apps/gnss_options.h"

namespace giocal {

namespace po = boost::program_options;

void addGnssOptions(po::options_description& opts) {
  opts.add_options()(
      "gnss", po::value<std::string>()->default_value("tc"),
      "tc: double differences (tightly coupled); lc: position solutions (--pos); single: one "
      "receiver, no base (time-differenced phase, Doppler, single point positions)")(
      "pos", po::value<std::string>()->default_value(""), "the LC scheme's .pos file");
}

std::string lcPositions(const po::variables_map& vm) {
  const std::string gnss = vm["gnss"].as<std::string>();
  if (gnss != "tc" && gnss != "lc" && gnss != "single")
    throw po::error("--gnss must be tc, lc or single, not '" + gnss + "'");
  if ((gnss == "lc") != !vm["pos"].as<std::string>().empty()) {
    throw po::error("--gnss lc needs --pos <file.pos>, and --pos only goes with --gnss lc");
  }
  return vm["pos"].as<std::string>();
}

bool singleReceiver(const po::variables_map& vm) {
  return vm["gnss"].as<std::string>() == "single";
}

}  // namespace giocal
