// Running the lutbake executable from a test: its exit status and its
// output (stdout and stderr together, or stdout alone), and scratch
// directories that start empty.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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

// The names of the files in dir, sorted.
inline std::vector<std::string> FileNames(const std::filesystem::path &dir) {
  std::vector<std::string> names;
  for (const auto &entry : std::filesystem::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The compilers an engine may build generated headers with: the suite's own
// C++ compiler and Debian's clang++ (scripts/setup.sh installs it; CMake
// finds it as LUTBAKE_CLANGXX). A missing one is returned as its
// "...-NOTFOUND" name, so that compiling with it fails loudly.
inline std::vector<std::string> HeaderCompilers() {
  return {LUTBAKE_TEST_CXX, LUTBAKE_TEST_CLANGXX};
}

// Compiles dir/main.cpp against the headers in dir as an engine would
// (-Wall -Wextra -Wpedantic -Werror -fno-exceptions) with `compiler` and
// runs it. Returns the shell command, which the caller prints on failure,
// and sets *status to the system() status (0: compiled and the program
// returned 0).
inline std::string CompileAndRun(const std::filesystem::path &dir, const std::string &compiler,
                                 const std::string &standard, int *status) {
  const std::string tag = std::filesystem::path(compiler).filename().string() + "_" + standard;
  const std::string exe = (dir / ("main_" + tag)).string();
  const std::string command =
      compiler + " -std=" + standard + " -Wall -Wextra -Wpedantic -Werror -fno-exceptions -I" +
      dir.string() + " " + (dir / "main.cpp").string() + " -o " + exe + " && " + exe;
  *status = std::system(command.c_str());
  return command;
}

// CompileAndRun with every compiler of HeaderCompilers() and each standard;
// one EXPECT per build.
#define LUTBAKE_EXPECT_COMPILES_AND_RUNS(dir, ...)                             \
  for (const std::string &compiler_ : ::lutbake::test::HeaderCompilers())      \
    for (const char *standard_ : {__VA_ARGS__}) {                              \
      int status_ = -1;                                                        \
      const std::string command_ =                                             \
          ::lutbake::test::CompileAndRun(dir, compiler_, standard_, &status_); \
      EXPECT_EQ(status_, 0) << command_;                                       \
    }

// Runs `command` through the shell: its stdout, and its wait status in *status.
inline std::string RunCommand(const std::string &command, int *status) {
  std::string out;
  FILE *pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  *status = ::pclose(pipe);
  return out;
}

}  // namespace lutbake::test
