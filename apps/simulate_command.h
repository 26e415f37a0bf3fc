// `giocal simulate --config <yaml> --out <dir> [--seed <n>]`.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

namespace giocal {

/// Refuses to write into a folder that already holds a dataset (nothing a user wrote is
/// overwritten).
void runSimulate(const std::string& config, const std::string& out, std::uint64_t seed,
                 std::ostream& log);

}  // namespace giocal
