// The options of the commands that make dataset folders: `giocal simulate` and `giocal import`.
#pragma once

namespace giocal {

/// argv[0] is the command's name; returns the exit status (throws as the other commands do).
int runSimulateCommand(int argc, char** argv);
int runImportCommand(int argc, char** argv);

}  // namespace giocal
