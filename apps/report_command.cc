#include "apps/report_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "common/io/output_set.h"

namespace giocal {
namespace {

// Debian's interpreter, which has python3-matplotlib (a python3 earlier on PATH may not).
constexpr const char* kPython = "/usr/bin/python3";

std::string reportScript() {
  if (const char* env = std::getenv("GIOCAL_REPORT_SCRIPT")) return env;
  return GIOCAL_REPORT_SCRIPT_PATH;
}

// Runs argv[0] with its arguments (no shell); returns its exit status.
int runProgram(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start " + args[0]);
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

void runReport(const ReportJob& job, std::ostream& log) {
  if (!std::filesystem::exists(job.run)) throw std::runtime_error(job.run + ": no such run");
  if (!job.overwrite && std::filesystem::exists(job.out + "/index.html")) {
    throw std::runtime_error(job.out + "/index.html exists; give --overwrite to replace it");
  }
  const std::string script = reportScript();
  if (!std::filesystem::exists(script))
    throw std::runtime_error(script + ": report script missing");
  if (runProgram({kPython, "-c", "import matplotlib"}) != 0) {
    throw std::runtime_error(std::string(kPython) +
                             " cannot import matplotlib: apt-get install python3-matplotlib");
  }
  OutputSet outputs(job.out);
  outputs.stagedPath("index.html", true);
  const int status = runProgram({kPython, script, job.run, outputs.staging(), job.data});
  if (status != 0) {
    throw std::runtime_error("report of " + job.run + " failed (" + script + " exit status " +
                             std::to_string(status) + ")");
  }
  for (const auto& e : std::filesystem::directory_iterator(outputs.staging())) {
    if (e.path().filename() != "index.html") outputs.stagedPath(e.path().filename().string());
  }
  outputs.commit();
  log << "  outputs: " << job.out << "/index.html\n";
}

}  // namespace giocal
