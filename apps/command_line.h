// Command-line plumbing every giocal command shares: option parsing with --help, and the
// nearest valid name for a misspelled option or command.
#pragma once

#include <boost/program_options.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace giocal {

/// Thrown after a command's help was printed: main() returns 0.
struct HelpShown : std::runtime_error {
  HelpShown() : std::runtime_error("help shown") {}
};

/// Parses and checks a sub-command's options. With --help or -h anywhere, prints `summary`, the
/// options with their defaults and `example` to standard output and throws HelpShown. An
/// unknown option is reported with the nearest valid one ("did you mean '--data'?").
boost::program_options::variables_map parseCommand(
    int argc, char** argv, const boost::program_options::options_description& opts,
    const std::string& summary, const std::string& example);

/// The candidate closest to `word` in edit distance, if it is close enough to be a likely
/// misspelling (at most a third of its length, at least 1 edit, at most 3); else empty.
std::string likelyMeant(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace giocal
