// `giocal observability`: on the flat paper preset p_b_m.z is named unobservable and the
// extrinsic yaw weak, the rest informed; on a straight drive (no turns) the yaw-rate scale, the
// lateral lever arm, pitch and yaw are named weak, with the advice to turn; and the numbers in the
// printed table are those of observability.json. With one receiver (a rover-only drive) the
// analysis uses the rover's own phase and agrees with the factor graph's sigmas.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "run_giocal.h"
#include "temp_dir.h"

namespace giocal {
namespace {

std::string run(const std::string& args) { return test::runGiocal(args).out; }

nlohmann::json analyze(const test::TempDir& dir, const std::string& preset, std::string* log) {
  const std::string data = dir.file("data");
  run("simulate --config " + preset + " --out " + data + " --seed 12");
  *log = run("observability --data " + data + " --out " + dir.file("obs"));
  std::ifstream in(dir.file("obs/observability.json"));
  EXPECT_TRUE(in.good()) << *log;
  return nlohmann::json::parse(in);
}

bool names(const nlohmann::json& list, const std::string& what) {
  for (const auto& x : list)
    if (x.get<std::string>() == what) return true;
  return false;
}

TEST(Observability, PaperPresetNamesPbmzUnobservableAndYawWeak) {
  test::TempDir dir;
  std::string log;
  const nlohmann::json j =
      analyze(dir, std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml", &log);
  EXPECT_FALSE(j["p_b_m_z"]["observable"].get<bool>()) << log;
  EXPECT_NE(log.find("UNOBSERVABLE (planar motion)"), std::string::npos) << log;
  EXPECT_TRUE(names(j["weak"], "yaw of q_b_m")) << log;
  for (const char* k : {"s_v", "s_w", "p_b_m.x", "p_b_m.y", "roll of q_b_m", "pitch of q_b_m"}) {
    EXPECT_FALSE(names(j["weak"], k)) << k << "\n" << log;
    EXPECT_LT(j["expected_sigma"][k].get<double>(), 0.2 * j["prior_sigma"][k].get<double>()) << k;
  }
  // The yaw rate scale is learnt in the circle, after the straight: the windows say when.
  const auto& w = j["windows"];
  ASSERT_GE(w.size(), 4u);
  EXPECT_GT(w[0]["sigma"]["s_w"].get<double>(), 0.5 * j["prior_sigma"]["s_w"].get<double>());
  EXPECT_GT(w[2]["turned_left_deg"].get<double>(), 200.0);
  // The printed window table carries the JSON's numbers.
  std::ostringstream row;
  row << std::fixed;
  row.precision(5);
  row << w[1]["sigma"]["s_v"].get<double>();
  EXPECT_NE(log.find(row.str()), std::string::npos) << row.str() << "\n" << log;
}

TEST(Observability, StraightDriveNamesWhatOnlyTurnsInform) {
  test::TempDir dir;
  std::ifstream in(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  std::stringstream yaml;
  yaml << in.rdbuf();
  std::string straight = std::regex_replace(yaml.str(), std::regex("- \\{type: arc[^}]*\\}"),
                                            "- {type: straight, duration: 106.0}");
  straight = std::regex_replace(straight, std::regex("nav_file: \\.\\./\\.\\./"),
                                "nav_file: " + std::string(GIOCAL_SOURCE_DIR) + "/");
  ASSERT_EQ(straight.find("type: arc"), std::string::npos);
  std::string log;
  const nlohmann::json j = analyze(dir, dir.write("straight.yaml", straight), &log);
  // A body that does not turn says nothing of the lever arm: both axes stay at the prior.
  for (const char* k : {"s_w", "p_b_m.x", "p_b_m.y", "pitch of q_b_m", "yaw of q_b_m"}) {
    EXPECT_TRUE(names(j["weak"], k)) << k << "\n" << log;
  }
  EXPECT_FALSE(names(j["weak"], "s_v")) << log;
  EXPECT_NE(log.find("advice: s_w: turning"), std::string::npos) << log;
}

TEST(Observability, WithOneReceiverItsExpectedSigmasAreTheFactorGraphs) {
  test::TempDir dir;
  const std::string data = dir.file("data");
  run("simulate --config " + std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml --out " +
      data + " --seed 12 --no-base");
  // No base in dataset.yaml: one receiver without being asked, as calibrate does.
  const std::string log = run("observability --data " + data + " --out " + dir.file("obs"));
  EXPECT_NE(log.find("one receiver's time-differenced carrier phase"), std::string::npos) << log;
  run("calibrate --data " + data + " --estimator fgo --no-validate --quiet --out " +
      dir.file("fgo"));
  std::ifstream obs_file(dir.file("obs/observability.json")),
      fgo_file(dir.file("fgo/summary.json"));
  ASSERT_TRUE(obs_file.good() && fgo_file.good()) << log;
  const nlohmann::json obs = nlohmann::json::parse(obs_file), fgo = nlohmann::json::parse(fgo_file);
  const nlohmann::json& sd = fgo["sd"];
  const std::vector<std::pair<std::string, double>> fgo_sigma = {
      {"s_v", sd["s_v"].get<double>()},
      {"s_w", sd["s_w"].get<double>()},
      {"p_b_m.x", sd["p_b_m"][0].get<double>()},
      {"p_b_m.y", sd["p_b_m"][1].get<double>()},
      {"roll of q_b_m", sd["rpy_b_m_deg"][0].get<double>()},
      {"pitch of q_b_m", sd["rpy_b_m_deg"][1].get<double>()}};
  for (const auto& [name, sigma] : fgo_sigma) {
    const double expected = obs["expected_sigma"][name].get<double>();
    EXPECT_NEAR(expected / sigma, 1.0, 0.3) << name << "\n" << log;
    EXPECT_LT(expected, 0.2 * obs["prior_sigma"][name].get<double>()) << name;
  }
  // The one weak state of this drive, for both.
  EXPECT_TRUE(names(obs["weak"], "yaw of q_b_m")) << log;
  EXPECT_NE(fgo["warnings"].dump().find("yaw of q_b_m is weakly observed"), std::string::npos);
  EXPECT_FALSE(obs["p_b_m_z"]["observable"].get<bool>()) << log;
  // One receiver has no position solution to hand the analysis.
  const test::GiocalResult refused =
      test::runGiocal("observability --data " + data + " --gnss single --pos x.pos");
  EXPECT_NE(refused.code, 0);
  EXPECT_NE(refused.out.find("--pos and --gnss single do not go together"), std::string::npos)
      << refused.out;
}

TEST(Observability, WithoutTruthItRunsOnGiocalRtksSolutionAndSaysWhatItCannotAssess) {
  test::TempDir dir;
  const std::string data = dir.file("data");
  run("simulate --config " + std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml --out " +
      data + " --seed 13");
  std::filesystem::remove(data + "/truth.csv");
  std::ifstream in(data + "/dataset.yaml");
  std::stringstream yaml;
  yaml << in.rdbuf();
  in.close();
  std::ofstream(data + "/dataset.yaml")
      << std::regex_replace(yaml.str(), std::regex("\\n *truth: truth.csv"), "");
  const std::string log = run("observability --data " + data + " --out " + dir.file("obs"));
  EXPECT_NE(log.find("motion from giocal rtk's solution"), std::string::npos) << log;
  EXPECT_NE(log.find("not assessed without truth.csv"), std::string::npos) << log;
  std::ifstream json(dir.file("obs/observability.json"));
  ASSERT_TRUE(json.good()) << log;
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_FALSE(j["p_b_m_z"]["assessed"].get<bool>());
  EXPECT_LT(j["expected_sigma"]["s_w"].get<double>(), 0.2 * j["prior_sigma"]["s_w"].get<double>());
  // No temporary solution is left behind.
  for (const auto& f : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    EXPECT_EQ(f.path().filename().string().rfind("giocal_observability_", 0), std::string::npos);
}

}  // namespace
}  // namespace giocal
