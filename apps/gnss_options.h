// The commands' GNSS scheme options: --gnss tc|lc|single and the LC scheme's --pos.
#pragma once

#include <boost/program_options.hpp>
#include <string>

namespace giocal {

void addGnssOptions(boost::program_options::options_description& opts);

/// The LC scheme's .pos file, empty for the TC (and single-receiver) scheme. Throws a
/// program_options error for an unknown scheme, and --gnss lc without --pos (or --pos without
/// it).
std::string lcPositions(const boost::program_options::variables_map& vm);

/// --gnss single: one receiver, no base.
bool singleReceiver(const boost::program_options::variables_map& vm);

}  // namespace giocal
