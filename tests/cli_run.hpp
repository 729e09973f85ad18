// A lesson binary run as a shell runs it (cli_tests: test_cli.cpp, test_exercises.cpp): its
// exit code and what it printed, stdout and stderr together.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace shadows::testing {

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// `env` goes before the command ("VAR=x "); `args` as a shell word list.
inline Result run(const std::string& lesson, const std::string& args, const std::string& env = {}) {
  const std::string command =
      env + std::string(SHADOWS_BINARY_DIR) + "/" + lesson + " " + args + " 2>&1";
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace shadows::testing
