// The giocal command interrupted while writing: outputs appear as a whole set or not at all, no
// temporary survives, a killed run's leftovers are swept by the next run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "common/io/data_error.h"
#include "common/io/output_set.h"
#include "sim/simulator.h"
#include "temp_dir.h"

extern char** environ;

namespace giocal {
namespace {

namespace fs = std::filesystem;

pid_t spawnGiocal(std::vector<std::string> args, const std::string& log) {
  args.insert(args.begin(), GIOCAL_BINARY);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

int waitExit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Waits until the run has written part of its trajectory into its staging folder.
bool waitUntilWriting(const std::string& out, pid_t pid) {
  const fs::path staged = fs::path(out) / (".giocal-partial." + std::to_string(pid));
  for (int i = 0; i < 6000; ++i) {
    std::error_code ec;
    if (fs::file_size(staged / "trajectory.csv", ec) > 20000 && !ec) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

std::vector<std::string> leftovers(const std::string& out) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string n = e.path().filename().string();
    if (n.find("giocal-partial") != std::string::npos || n.find("giocal-tmp") != std::string::npos)
      names.push_back(n);
  }
  return names;
}

std::string estimatorOf(const std::string& summary) {
  std::ifstream in(summary);
  return nlohmann::json::parse(in)["estimator"].get<std::string>();
}

std::string contentOf(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(InterruptedOutputs, ARunStoppedWhileWritingLeavesTheEarlierSetWholeAndNoTemporaries) {
  test::TempDir dir;
  const std::string data = dir.file("data"), out = dir.file("out");
  sim::writeDataset(
      sim::simulate(sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml"),
                    5),
      data);
  const std::vector<std::string> calibrate{"calibrate", "--data", data, "--out", out};

  // A complete EKF run: summary.json names the files with their sizes.
  ASSERT_EQ(waitExit(spawnGiocal(calibrate, dir.file("ekf.log"))), 0)
      << contentOf(dir.file("ekf.log"));
  // Piped, the run shows no progress line (ProgressLine draws only on a terminal).
  EXPECT_EQ(contentOf(dir.file("ekf.log")).find("of the data"), std::string::npos);
  const auto files = verifyOutputSet(out + "/summary.json");
  EXPECT_EQ(files.size(), 3u);  // calibration.csv, trajectory.csv, gnss.csv
  EXPECT_EQ(files.count("calibration.csv"), 1u);
  const std::string ekf_calibration = contentOf(out + "/calibration.csv");

  // A factor-graph run over it, stopped with SIGTERM and with SIGINT while writing: exit 128+sig,
  // the EKF's set untouched and consistent, nothing temporary left.
  std::vector<std::string> fgo = calibrate;
  fgo.insert(fgo.end(), {"--estimator", "fgo", "--overwrite"});
  for (int sig : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(sig);
    const pid_t pid = spawnGiocal(fgo, dir.file("fgo.log"));
    ASSERT_TRUE(waitUntilWriting(out, pid));
    kill(pid, sig);
    EXPECT_EQ(waitExit(pid), 128 + sig);
    EXPECT_NE(contentOf(dir.file("fgo.log")).find("interrupted by signal"), std::string::npos);
    EXPECT_TRUE(leftovers(out).empty()) << leftovers(out).front();
    EXPECT_NO_THROW(verifyOutputSet(out + "/summary.json"));
    EXPECT_EQ(estimatorOf(out + "/summary.json"), "ekf");
    EXPECT_EQ(contentOf(out + "/calibration.csv"), ekf_calibration);
  }

  // SIGKILL cannot be caught: the staging folder stays, the earlier set is still whole, and the
  // next run sweeps the leftovers and replaces the set as a unit.
  const pid_t killed = spawnGiocal(fgo, dir.file("fgo.log"));
  ASSERT_TRUE(waitUntilWriting(out, killed));
  kill(killed, SIGKILL);
  waitExit(killed);
  EXPECT_EQ(leftovers(out).size(), 1u);
  EXPECT_EQ(estimatorOf(out + "/summary.json"), "ekf");
  EXPECT_NO_THROW(verifyOutputSet(out + "/summary.json"));
  ASSERT_EQ(waitExit(spawnGiocal(fgo, dir.file("fgo.log"))), 0) << contentOf(dir.file("fgo.log"));
  EXPECT_TRUE(leftovers(out).empty());
  EXPECT_EQ(estimatorOf(out + "/summary.json"), "fgo");
  EXPECT_NO_THROW(verifyOutputSet(out + "/summary.json"));
}

TEST(OutputSet, SummaryChecksFindMixedAndIncompleteSets) {
  test::TempDir dir;
  {
    OutputSet set(dir.path());
    set.open("a.csv") << "1,2\n";
    const auto bytes = set.close("a.csv");
    set.open("summary.json", true) << "{\"files\": {\"a.csv\": " << bytes << "}}\n";
    // Nothing is in the folder before the commit.
    EXPECT_FALSE(fs::exists(dir.file("a.csv")));
    set.commit();
  }
  EXPECT_EQ(verifyOutputSet(dir.file("summary.json")).at("a.csv"), 4u);
  EXPECT_TRUE(leftovers(dir.path()).empty());
  dir.write("a.csv", "1,2\n3,4\n");  // another run's file beside this summary
  EXPECT_THROW(verifyOutputSet(dir.file("summary.json")), DataError);
  fs::remove(dir.file("a.csv"));
  EXPECT_THROW(verifyOutputSet(dir.file("summary.json")), DataError);
  fs::remove(dir.file("summary.json"));
  try {
    verifyOutputSet(dir.file("summary.json"));
    FAIL() << "a folder without summary.json passed";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("incomplete"), std::string::npos) << e.what();
  }
  // A set destroyed before its commit leaves nothing; a dead process's staging folder is swept.
  {
    OutputSet set(dir.path());
    set.open("b.csv") << "x\n";
  }
  EXPECT_FALSE(fs::exists(dir.file("b.csv")));
  EXPECT_TRUE(leftovers(dir.path()).empty());
  fs::create_directory(dir.file(".giocal-partial.999999999"));  // no such pid can run
  dir.write("x.csv.giocal-tmp.999999999", "half a li");
  dir.write("notes.tmp.999999999", "a user's file that only looks temporary");
  OutputSet next(dir.path());
  EXPECT_FALSE(fs::exists(dir.file(".giocal-partial.999999999")));
  EXPECT_FALSE(fs::exists(dir.file("x.csv.giocal-tmp.999999999")));
  EXPECT_TRUE(fs::exists(dir.file("notes.tmp.999999999")));
}

}  // namespace
}  // namespace giocal
