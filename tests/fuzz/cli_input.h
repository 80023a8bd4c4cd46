// A fuzz input of the cli target as a command line: one argument per line
// ('\n'), after argv[0] "lutbake"; a last line without '\n' is an argument
// too. Shared by tests/fuzz/cli_fuzzer.cpp and the corpus replay.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace lutbake::fuzz {

inline std::vector<std::string> CommandLineOf(const char *data, size_t size) {
  std::vector<std::string> args = {"lutbake"};
  std::string arg;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += data[i];
    }
  }
  if (!arg.empty()) args.push_back(arg);
  return args;
}

}  // namespace lutbake::fuzz
