// Running the lutbake executable from a test: its exit status and its
// output (stdout and stderr together, or stdout alone), and scratch
// directories that start empty.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace lutbake::test {

struct CommandResult {
  int status;
  std::string output;
};

// stdoutOnly: capture stdout and drop stderr (for --json output).
inline CommandResult Lutbake(const std::string &args, bool stdoutOnly = false) {
  namespace fs = std::filesystem;
  const std::string log =
      (fs::temp_directory_path() / ("lutbake_cli_" + std::to_string(::getpid()) + ".log")).string();
  const std::string command = std::string(LUTBAKE_BINARY) + " " + args + " > " + log +
                              (stdoutOnly ? " 2>/dev/null" : " 2>&1");
  const int raw = std::system(command.c_str());
  std::ifstream in(log);
  std::string output((std::istreambuf_iterator<char>(in)), {});
  fs::remove(log);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, output};
}

inline std::filesystem::path Scratch(const std::string &name) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("lutbake_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

// Compiles dir/main.cpp against the headers in dir as an engine would
// (-Wall -Wextra -Wpedantic -Werror -fno-exceptions) and runs it. Returns
// the shell command, which the caller prints on failure, and sets *status to
// the system() status (0: compiled and the program returned 0).
inline std::string CompileAndRun(const std::filesystem::path &dir, const std::string &standard,
                                 int *status) {
  const std::string exe = (dir / ("main_" + standard)).string();
  const std::string command = std::string(LUTBAKE_TEST_CXX) + " -std=" + standard +
                              " -Wall -Wextra -Wpedantic -Werror -fno-exceptions -I" +
                              dir.string() + " " + (dir / "main.cpp").string() + " -o " + exe +
                              " && " + exe;
  *status = std::system(command.c_str());
  return command;
}

}  // namespace lutbake::test
