// `giocal check` compares the dataset's initial guess of R_b_m with the mounting the drive shows:
// a guess turned by 90 degrees is named, the simulator's guess (within its 5-degree sigma) is not.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "run_giocal.h"
#include "temp_dir.h"

namespace giocal {
namespace {

std::string run(const std::string& args) { return test::runGiocal(args).out; }

TEST(CheckMounting, AGuessFarFromTheDriveIsNamed) {
  test::TempDir dir;
  const std::string data = dir.file("paper");
  run("simulate --config " + std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml --out " +
      data + " --seed 4");
  const std::string fine = run("check --data " + data);
  EXPECT_NE(fine.find("mounting from the data: rpy_b_m"), std::string::npos) << fine;
  EXPECT_EQ(fine.find("WARNING"), std::string::npos) << fine;

  std::ifstream in(data + "/dataset.yaml");
  std::stringstream yaml;
  yaml << in.rdbuf();
  in.close();
  // The guess turned by 90 degrees of roll.
  const std::string turned = std::regex_replace(
      std::regex_replace(yaml.str(), std::regex("q_b_m: \\[[^\\]]*\\]"),
                         "q_b_m: [0.7071068, 0.7071068, 0, 0]"),
      std::regex("\\n *rpy_b_m_deg: \\[[^\\]]*\\]"), "", std::regex_constants::format_first_only);
  std::ofstream(data + "/dataset.yaml") << turned;
  const std::string warned = run("check --data " + data);
  EXPECT_NE(warned.find("WARNING: the initial guess of R_b_m is"), std::string::npos) << warned;
}

}  // namespace
}  // namespace giocal
