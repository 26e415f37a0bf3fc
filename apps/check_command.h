// `giocal check --data <dir>`: reads every file of a dataset folder and reports what it holds.
#pragma once

#include <iosfwd>

#include "common/io/dataset_folder.h"

namespace giocal {

/// Throws DataError (file:line: problem) on the first bad input; what it finds short of that
/// (warnings, unusable conditions) is also kept in `data.findings`.
void runCheck(DatasetFolder& data, std::ostream& out);

}  // namespace giocal
