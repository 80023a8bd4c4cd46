#include "cli_util.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <sstream>

#include "interrupt.h"
#include "lutbake/api/bake.h"
#include "lutbake/api/identify.h"
#include "lutbake/core/cancellation.h"

namespace lutbake::cli {

std::vector<std::string> SplitList(const std::string &list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');) items.push_back(item);
  if (!list.empty() && list.back() == ',') items.emplace_back();
  return items;
}

CLI::Validator OneOf(std::vector<std::string> names) {
  const std::string accepted = JoinNames(names);
  return CLI::Validator(
      [names, accepted](std::string &value) -> std::string {
        for (const std::string &n : names)
          if (value == n) return {};
        return "'" + value + "' is not accepted; accepted: " + accepted + DidYouMean(value, names);
      },
      "one of: " + accepted);
}

CLI::Validator ListOf(std::vector<std::string> names) {
  const std::string accepted = JoinNames(names);
  return CLI::Validator(
      [names, accepted](std::string &value) -> std::string {
        const std::vector<std::string> items = SplitList(value);
        if (items.empty()) return "empty list; accepted: a comma-separated subset of " + accepted;
        for (size_t i = 0; i < items.size(); ++i) {
          bool known = false;
          for (const std::string &n : names) known = known || items[i] == n;
          if (!known)
            return (items.size() == 1
                        ? "'" + items[i] + "' is not accepted"
                        : "'" + value + "' names '" + items[i] + "', which is not accepted") +
                   "; accepted: a comma-separated subset of " + accepted +
                   DidYouMean(items[i], names);
          for (size_t j = 0; j < i; ++j)
            if (items[j] == items[i]) return "'" + value + "' names '" + items[i] + "' twice";
        }
        return {};
      },
      "comma-separated subset of: " + accepted);
}

CLI::Validator RealInRange(double lo, double hi, const std::string &accepted) {
  return CLI::Validator(
      [lo, hi, accepted](std::string &value) { return RealNumberProblem(value, lo, hi, accepted); },
      accepted);
}

CLI::Validator CppNamespace() {
  return CLI::Validator([](std::string &value) { return NamespaceProblem(value); },
                        "C++ namespace");
}

void AddModelOptions(CLI::App &app, std::map<std::string, std::string> &values,
                     const std::vector<std::string> &only) {
  for (const ModelOption &m : ModelOptions()) {
    if (!only.empty() && std::find(only.begin(), only.end(), m.option) == only.end()) continue;
    values[m.option] = m.defaultValue;
    app.add_option("--" + m.option, values[m.option],
                   m.meaning + (only.empty() ? "; tables " + JoinNames(m.tables) : ""))
        ->capture_default_str()
        ->check(OneOf(m.accepted));
  }
}

void AddConventionOptions(CLI::App &app, std::map<std::string, std::string> &values) {
  for (const ConventionOption &c : ConventionOptions()) {
    CLI::Option *option = app.add_option("--" + c.name, values[c.name], c.help);
    option->type_name(c.typeName);
    if (!c.accepted.empty()) option->check(c.list ? ListOf(c.accepted) : OneOf(c.accepted));
  }
}

void AddSeedOption(CLI::App &app, uint64_t &seed, const std::string &seedHelp) {
  app.add_option("--seed", seed, seedHelp)
      ->capture_default_str()
      ->type_name("S")
      ->check(InRange<uint64_t>(0, UINT64_MAX, "(any unsigned 64-bit integer)"));
}

void AddThreadsOption(CLI::App &app, int &threads, const std::string &threadsHelp) {
  app.add_option("--threads", threads, "Worker threads (default: all cores)" + threadsHelp)
      ->type_name("N")
      ->check(InRange(1, 1024, "threads"));
}

int RunLibraryCall(const std::string &command, const std::string &outDir,
                   const std::function<void()> &call) {
  // On a terminal a progress bar may be drawn: the error line replaces it.
  const std::string start = "lutbake " + command + ": ";
  const std::string line = (::isatty(STDERR_FILENO) != 0 ? "\r\033[K" : "") + start;
  try {
    call();
    return 0;
  } catch (const Cancelled &c) {
    std::cerr << line << "interrupted by " << SignalName(c.reason()) << "; nothing written to "
              << outDir << "\n";
    return 128 + c.reason();
  } catch (const Error &e) {
    std::cerr << line << e.what() << "\n";
    return e.kind() == Error::Kind::kUsage ? 2 : e.kind() == Error::Kind::kUnreadable ? 3 : 1;
  } catch (const std::bad_alloc &) {
    std::cerr << line << "out of memory\n";
    return 1;
  }
}

}  // namespace lutbake::cli
