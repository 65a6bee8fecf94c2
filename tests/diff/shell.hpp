// Runs a command line with /bin/sh for the command-line tests: its exit status and its stdout
// and stderr together.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace glpt::cli {

struct Result {
  int status = -1;
  std::string out;  // stdout and stderr together
};

inline Result shell(const std::string& command) {
  Result r;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace glpt::cli
