// The command line as users expect: --help for every command (options, defaults, an example),
// --version, and a misspelled option or command answered with the nearest valid name.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "run_giocal.h"

namespace giocal {
namespace {

using Result = test::GiocalResult;
const auto run = test::runGiocal;

TEST(CommandLine, EveryCommandHasHelpWithDefaultsAndAnExample) {
  for (const char* command : {"check", "simulate", "rtk", "calibrate", "compare", "deadreckon",
                              "import", "export", "report", "observability"}) {
    const Result r = run(std::string(command) + " --help");
    EXPECT_EQ(r.code, 0) << command << ": " << r.out;
    EXPECT_EQ(r.out.rfind(std::string("giocal ") + command + ": ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("example:\n  giocal " + std::string(command) + " "), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("  --"), std::string::npos) << r.out;
  }
  EXPECT_NE(run("calibrate --help").out.find("--estimator arg (=ekf)"), std::string::npos);
  // Help wins over the required options that are missing.
  EXPECT_EQ(run("deadreckon -h").code, 0);
}

TEST(CommandLine, VersionIsPrinted) {
  const Result r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, std::string("giocal ") + GIOCAL_VERSION + "\n");
}

TEST(CommandLine, AMisspelledOptionIsAnsweredWithTheNearestOne) {
  Result r = run("calibrate --dta /nowhere --out /nowhere");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("unrecognised option '--dta'; did you mean '--data'?"), std::string::npos)
      << r.out;
  r = run("deadreckon --data x --calibrtion truth --out y");
  EXPECT_NE(r.out.find("did you mean '--calibration'?"), std::string::npos) << r.out;
  // Nothing near: no guess.
  r = run("rtk --zzzzzzzz 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out.find("did you mean"), std::string::npos) << r.out;
}

TEST(CommandLine, AMisspelledCommandIsAnsweredWithTheNearestOne) {
  const Result r = run("calibrat --data x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("unknown command 'calibrat'; did you mean 'calibrate'?"), std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace giocal
