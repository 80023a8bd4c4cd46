#include "cli_util.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <thread>

namespace lutbake::cli {

std::vector<std::string> SplitList(const std::string &list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');) items.push_back(item);
  if (!list.empty() && list.back() == ',') items.emplace_back();
  return items;
}

std::string JoinNames(const std::vector<std::string> &names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

CLI::Validator OneOf(std::vector<std::string> names) {
  const std::string accepted = JoinNames(names);
  return CLI::Validator(
      [names, accepted](std::string &value) -> std::string {
        for (const std::string &n : names)
          if (value == n) return {};
        return "'" + value + "' is not accepted; accepted: " + accepted;
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
            return "'" + value + "' names '" + items[i] +
                   "', which is not accepted; accepted: a comma-separated subset of " + accepted;
          for (size_t j = 0; j < i; ++j)
            if (items[j] == items[i]) return "'" + value + "' names '" + items[i] + "' twice";
        }
        return {};
      },
      "comma-separated subset of: " + accepted);
}

CLI::Validator RealInRange(double lo, double hi, const std::string &accepted) {
  return CLI::Validator(
      [lo, hi, accepted](std::string &value) -> std::string {
        char *end = nullptr;
        errno = 0;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || end != value.c_str() + value.size() || errno == ERANGE ||
            !std::isfinite(v))
          return "'" + value + "' is not a number; accepted: " + accepted;
        if (!(v >= lo && v <= hi)) return "'" + value + "' is out of range; accepted: " + accepted;
        return {};
      },
      accepted);
}

CLI::Validator CppNamespace() {
  return CLI::Validator(
      [](std::string &value) -> std::string {
        // A C++ namespace path: identifiers separated by "::".
        bool ok = !value.empty();
        bool start = true;
        for (size_t i = 0; ok && i < value.size(); ++i) {
          const char c = value[i];
          if (c == ':' && i + 1 < value.size() && value[i + 1] == ':' && !start) {
            ++i;
            start = true;
            continue;
          }
          const bool alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
          const bool digit = c >= '0' && c <= '9';
          ok = alpha || (digit && !start);
          start = false;
        }
        if (!ok || start)
          return "'" + value + "' is not a C++ namespace name (e.g. my_engine::luts)";
        return {};
      },
      "C++ namespace");
}

std::string PrepareOutputDirectory(const std::string &dir, bool *created, bool *usageError) {
  namespace fs = std::filesystem;
  std::error_code ec;
  *created = false;
  *usageError = false;
  if (dir.empty()) {
    *usageError = true;
    return "is empty; accepted: a directory, created if missing";
  }
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) {
      *usageError = true;
      return "exists and is not a directory; accepted: a directory, created if missing";
    }
  } else {
    *created = fs::create_directories(dir, ec);
    if (ec) return "cannot create the directory: " + ec.message();
  }
  // Probe by creating a file, which also catches read-only file systems.
  // An anonymous one (O_TMPFILE) where the file system has them: the kernel
  // frees it however the process ends, so a kill never leaves a probe
  // behind. Elsewhere a named probe, removed at once; a probe left by a
  // killed run (its pid no longer exists) is removed here.
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
    for (const auto &entry : fs::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      const std::string prefix = ".lutbake-probe-";
      if (file.rfind(prefix, 0) != 0) continue;
      const long pid = std::strtol(file.c_str() + prefix.size(), nullptr, 10);
      if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
        fs::remove(entry.path(), ec);
    }
    const std::string probe =
        (fs::path(dir) / (".lutbake-probe-" + std::to_string(::getpid()))).string();
    fd = ::open(probe.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0600);
    if (fd >= 0) ::unlink(probe.c_str());
  }
  if (fd < 0) {
    const std::string reason = std::strerror(errno);
    if (*created) fs::remove(dir, ec);
    return "is not writable: " + reason;
  }
  ::close(fd);
  return {};
}

int PrepareOutputOrComplain(const std::string &command, const std::string &dir, bool *created) {
  bool usageError = false;
  const std::string problem = PrepareOutputDirectory(dir, created, &usageError);
  if (problem.empty()) return 0;
  std::fprintf(stderr, "lutbake %s: --out %s: %s\n", command.c_str(), dir.c_str(), problem.c_str());
  return usageError ? 2 : 1;
}

void AddModelOptions(CLI::App &app, std::string &ndf, std::string &smith) {
  app.add_option("--ndf", ndf, "Microfacet distribution")
      ->capture_default_str()
      ->check(OneOf({"ggx", "beckmann"}));
  app.add_option("--smith", smith, "Smith masking-shadowing form")
      ->capture_default_str()
      ->check(OneOf({"correlated", "separable"}));
}

void AddSheenOptions(CLI::App &app, std::string &visibility, std::string &alpha) {
  app.add_option("--sheen-visibility", visibility,
                 "sheen_E, sheen_Eavg: charlie (Estevez-Kulla's fitted Lambda, as glTF's "
                 "KHR_materials_sheen gives it) or ashikhmin (1 / (4 (mu_i + mu_o - mu_i mu_o)))")
      ->capture_default_str()
      ->check(OneOf({"charlie", "ashikhmin"}));
  app.add_option("--sheen-alpha", alpha,
                 "sheen_E, sheen_Eavg: the Charlie alpha from the roughness axis r "
                 "(sheenRoughness): linear alpha = r, squared alpha = r^2 (Filament's cloth, and "
                 "the glTF extension's sample code)")
      ->capture_default_str()
      ->check(OneOf({"linear", "squared"}));
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

int ThreadCount(int requested) {
  return requested > 0 ? requested
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void RemoveCreatedDirectory(const std::string &dir, bool created) {
  if (!created) return;
  std::error_code ec;
  std::filesystem::remove(dir, ec);  // only succeeds if still empty
}

}  // namespace lutbake::cli
