// `giocal check --data <dir>`: reads every file of a dataset folder and reports what it holds.
#pragma once

#include <iosfwd>
#include <string>

namespace giocal {

/// Throws DataError (file:line: problem) on the first bad input.
void runCheck(const std::string& folder, std::ostream& out);

}  // namespace giocal
