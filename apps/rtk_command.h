// The option parsing of `giocal rtk`: kinematic RTK of a rover and base RINEX pair to a .pos.
#pragma once

namespace giocal {

/// argv[0] is the command's name; returns the exit status (throws as the other commands do).
int runRtkCommand(int argc, char** argv);

}  // namespace giocal
