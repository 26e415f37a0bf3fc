// The commands' GNSS scheme options: --gnss tc|lc|single and the LC scheme's --pos.
#pragma once

#include <boost/program_options.hpp>
#include <string>

namespace giocal {

void addGnssOptions(boost::program_options::options_description& opts);

/// The LC scheme's .pos file, empty for the TC (and single-receiver) scheme. Throws a
/// program_options error for an unknown scheme, --gnss lc without --pos (or --pos without it),
/// and --gnss single where the command has no such scheme (single_allowed false).
std::string lcPositions(const boost::program_options::variables_map& vm,
                        bool single_allowed = false);

/// --gnss single: one receiver, no base.
bool singleReceiver(const boost::program_options::variables_map& vm);

}  // namespace giocal
