#include "apps/command_line.h"

#include <algorithm>
#include <iostream>

namespace po = boost::program_options;

namespace giocal {

namespace {

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// "--dta=x" -> "dta"
std::string bareOption(std::string token) {
  token.erase(0, token.find_first_not_of('-'));
  return token.substr(0, token.find('='));
}

}  // namespace

std::string nearestName(const std::string& word, const std::vector<std::string>& candidates) {
  const size_t limit = std::min<size_t>(3, std::max<size_t>(1, word.size() / 3));
  std::string best;
  size_t best_distance = limit + 1;
  for (const std::string& c : candidates) {
    const size_t d = editDistance(word, c);
    if (d < best_distance) best_distance = d, best = c;
  }
  return best;
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
    const std::string near = nearestName(bareOption(e.get_option_name()), names);
    throw po::error(std::string(e.what()) +
                    (near.empty() ? "" : "; did you mean '--" + near + "'?") +
                    " (--help lists the options)");
  }
  po::notify(vm);
  return vm;
}

}  // namespace giocal
