// `giocal simulate --config <yaml> --out <dir> [--seed <n>]`.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

/// Refuses to write into a folder that already holds a dataset (nothing a user wrote is
/// overwritten); the dataset's files appear together, or none when `stop` is requested.
void runSimulate(const std::string& config, const std::string& out, std::uint64_t seed,
                 std::ostream& log, const StopRequest* stop = nullptr);

}  // namespace giocal
