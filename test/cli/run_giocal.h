// runGiocal: the giocal binary (or another program) run with arguments, its standard output and
// error together.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace giocal::test {

struct GiocalResult {
  std::string out;  // standard output and error
  int code = -1;    // exit status
};

/// `program` run with arguments through the shell.
inline GiocalResult runProgram(const std::string& program, const std::string& args) {
  const std::string cmd = program + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  GiocalResult r;
  char buf[512];
  while (p && std::fgets(buf, sizeof(buf), p)) r.out += buf;
  if (p) r.code = WEXITSTATUS(pclose(p));
  return r;
}

#ifdef GIOCAL_BINARY
inline GiocalResult runGiocal(const std::string& args) { return runProgram(GIOCAL_BINARY, args); }

/// runGiocal that expects the command to succeed (a gtest failure naming it otherwise).
inline GiocalResult runGiocalOk(const std::string& args) {
  const GiocalResult r = runGiocal(args);
  EXPECT_EQ(r.code, 0) << args << "\n" << r.out;
  return r;
}
#endif

}  // namespace giocal::test
