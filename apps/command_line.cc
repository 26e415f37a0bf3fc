#include "apps/command_line.h"

#include <algorithm>
#include <iostream>

#include "common/io/nearest_name.h"

namespace po = boost::program_options;

namespace giocal {

namespace {

/// "--dta=x" -> "dta"
std::string bareOption(std::string token) {
  token.erase(0, token.find_first_not_of('-'));
  return token.substr(0, token.find('='));
}

}  // namespace

std::string likelyMeant(const std::string& word, const std::vector<std::string>& candidates) {
  return nearestName(word, candidates, std::min<size_t>(3, std::max<size_t>(1, word.size() / 3)));
}

po::variables_map parseCommand(int argc, char** argv, const po::options_description& opts,
                               const std::string& summary, const std::string& example) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << summary << "\n\n" << opts << "\nexample:\n  " << example << "\n";
      throw HelpShown();
    }
  }
  po::variables_map vm;
  try {
    po::store(po::parse_command_line(argc, argv, opts), vm);
  } catch (const po::unknown_option& e) {
    std::vector<std::string> names;
    for (const auto& o : opts.options()) names.push_back(o->long_name());
    const std::string near = likelyMeant(bareOption(e.get_option_name()), names);
    throw po::error(std::string(e.what()) +
                    (near.empty() ? "" : "; did you mean '--" + near + "'?") +
                    " (--help lists the options)");
  }
  po::notify(vm);
  return vm;
}

}  // namespace giocal
