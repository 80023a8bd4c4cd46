// `lutbake bake` under kills, signals, a full disk, a file size limit and a
// directory made read-only: no final name ever holds a partial file or a
// file of another run than the rest of the set, the next run cleans up and
// succeeds, SIGINT / SIGTERM end with 130 / 143 and one line, and write
// errors end with 1, the file's name and the reason.
#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lutbake/formats/output_transaction.h"
#include "lutbake/api/presets.h"
#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "support/cli_run.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// How to start a child: a file size limit, another user.
struct SpawnOptions {
  long fileSizeLimit = -1;  // bytes; RLIMIT_FSIZE, SIGXFSZ left at its default
  bool asNobody = false;    // setuid/setgid 65534 (root ignores permissions)
};

// Starts `lutbake args...` with stdout and stderr in `log`.
pid_t Spawn(const std::vector<std::string> &args, const fs::path &log,
            const SpawnOptions &options = {}) {
  std::vector<std::string> all = {LUTBAKE_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char *> argv;
  for (std::string &a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string logPath = log.string();
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  // The child: only async-signal-safe calls until exec.
  const int fd = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (fd < 0) ::_exit(126);
  ::dup2(fd, 1);
  ::dup2(fd, 2);
  if (options.fileSizeLimit >= 0) {
    const rlimit limit{static_cast<rlim_t>(options.fileSizeLimit),
                       static_cast<rlim_t>(options.fileSizeLimit)};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  if (options.asNobody &&
      (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0))
    ::_exit(125);
  ::execv(argv[0], argv.data());
  ::_exit(127);
}

// Waits at most `limit` for the child; its raw wait status, or -1 (then it
// is killed).
int WaitFor(pid_t pid, std::chrono::milliseconds limit) {
  const auto end = Clock::now() + limit;
  int status = 0;
  while (Clock::now() < end) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

std::string ReadAll(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::map<std::string, std::string> Contents(const fs::path &dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto &entry : fs::directory_iterator(dir))
    files[entry.path().filename().string()] = ReadAll(entry.path());
  return files;
}

std::vector<std::string> Lines(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The set every test bakes: four tables in every format with error maps
// (E, Eavg, Favg, dfg as .exr, .bin, .h and .err.exr, and kulla_conty.h).
std::vector<std::string> SmallSet(const fs::path &out, int seed, int size = 16) {
  return {"bake",
          "--out",
          out.string(),
          "--tables",
          "E,Eavg,Favg,dfg",
          "--size",
          std::to_string(size),
          "--samples",
          "16",
          "--seed",
          std::to_string(seed),
          "--format",
          "exr,bin,header",
          "--error-map",
          "--threads",
          "1"};
}

// The set the kills interrupt: the same four tables in every format (one
// of each file name: png16, not png8; the binary16 forms of dds and js) and
// the shader functions in every language: 4 x 14 table files, kulla_conty.h
// and lutbake.{glsl,hlsl,wgsl,metal}.
std::vector<std::string> EveryFormatSet(const fs::path &out, int seed) {
  std::vector<std::string> args = SmallSet(out, seed);
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--format")
      args[i + 1] =
          "exr,bin,header,png16,ktx2,dds-half,inc,js-half,ts,glsl-array,hlsl-array,wgsl-array,"
          "msl-array";
  args.insert(args.end(), {"--shader", "glsl,hlsl,wgsl,msl"});
  return args;
}
constexpr size_t kEveryFormatSetFiles = 4 * 14 + 1 + 4 + 1;  // and lutbake-set.json

bool EndsWith(const std::string &text, const std::string &suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A bake that runs about a second (dfg 512 x 512 by the quadrature on one
// thread), to signal or disturb while it runs.
std::vector<std::string> LongBake(const fs::path &out) {
  return {"bake", "--out",     out.string(), "--tables", "dfg",           "--size",
          "512",  "--threads", "1",          "--format", "exr,bin,header"};
}

// The commandLine of lutbake-set.json, after checking that it lists files
// (ReadSetManifest gives none for a file that does not parse).
std::string SetManifestRun(const fs::path &file) {
  if (lutbake::ReadSetManifest(file.parent_path().string()).empty())
    throw lutbake::IoError(file.string() + ": lists no file or does not parse");
  const std::string text = ReadAll(file), key = "\"commandLine\": \"";
  const size_t at = text.find(key);
  if (at == std::string::npos) throw lutbake::IoError(file.string() + ": no commandLine");
  return text.substr(at + key.size(), text.find('"', at + key.size()) - at - key.size());
}

// The commandLine a final file records (the run it belongs to), after
// reading it whole with the library's reader for its format; throws IoError
// on a file that does not parse.
std::string RunOf(const fs::path &file) {
  const std::string path = file.string(), name = file.filename().string();
  const auto find = [&](const std::vector<std::pair<std::string, std::string>> &metadata) {
    for (const auto &[key, value] : metadata)
      if (key == "commandLine") return value;
    throw lutbake::IoError(path + ": no commandLine");
  };
  if (name == lutbake::kSetManifestName) return SetManifestRun(file);
  if (EndsWith(name, ".exr")) return find(lutbake::ReadExrTable(path).metadata);
  if (EndsWith(name, ".bin")) return find(lutbake::ReadBinaryTable(path).metadata);
  if (EndsWith(name, ".png")) return find(lutbake::ReadPngTable(path).metadata);
  if (EndsWith(name, ".ktx2")) return find(lutbake::ReadKtx2Table(path).metadata);
  if (EndsWith(name, ".dds")) return find(lutbake::ReadDdsTable(path).metadata);
  const bool functions = name.rfind("kulla_conty", 0) == 0 || name.rfind("lutbake.", 0) == 0;
  if (!functions && !EndsWith(name, ".h"))
    return find(lutbake::ReadSourceTable(path).metadata);  // .inc .js .ts .glsl ...
  if (functions) {
    // Functions, no table: its comment and its closing line (the shader
    // files end with a function's closing brace).
    const std::string text = ReadAll(file);
    if (text.find("#endif") == std::string::npos &&
        text.find("}  // namespace") == std::string::npos && !EndsWith(text, "}\n\n"))
      throw lutbake::IoError(path + ": truncated");
    const std::string key = "//   commandLine: ";
    const size_t at = text.find(key);
    if (at == std::string::npos) throw lutbake::IoError(path + ": no commandLine");
    return text.substr(at + key.size(), text.find('\n', at) - at - key.size());
  }
  return find(lutbake::ReadHeaderValues(path).metadata);
}

// Every file under a final name parses, and all record the same run; the
// number of final files (temporaries are counted in *temporaries).
size_t ExpectOneRun(const fs::path &dir, const std::string &context, size_t *temporaries) {
  std::string run;
  size_t finals = 0;
  *temporaries = 0;
  for (const auto &entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (lutbake::IsTemporaryName(name)) {
      ++*temporaries;
      continue;
    }
    ++finals;
    try {
      const std::string of = RunOf(entry.path());
      if (run.empty()) run = of;
      EXPECT_EQ(of, run) << context << ": " << name << " belongs to another run";
    } catch (const std::exception &e) {
      ADD_FAILURE() << context << ": " << name << " does not parse: " << e.what();
    }
  }
  return finals;
}

void ExpectNoTemporary(const fs::path &dir, const std::string &context) {
  for (const auto &[name, content] : Contents(dir))
    EXPECT_FALSE(lutbake::IsTemporaryName(name) || name.find(".tmp") != std::string::npos)
        << context << ": temporary left: " << name;
}

TEST(Reliability, FiftyFiveKillsNeverLeaveATornOrMixedSet) {
  const fs::path out = lutbake::test::Scratch("kills");
  const fs::path log = out.string() + ".log";
  // An uninterrupted run: its duration spreads the kills, and its files
  // are the first "previous set".
  auto start = Clock::now();
  ASSERT_EQ(WaitFor(Spawn(EveryFormatSet(out, 0), log), std::chrono::seconds(60)), 0)
      << ReadAll(log);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  size_t temporaries = 0;
  ASSERT_EQ(ExpectOneRun(out, "first run", &temporaries), kEveryFormatSetFiles);
  std::mt19937 random(18);
  std::uniform_real_distribution<double> moment(0.0, 1.1 * seconds);
  std::map<std::string, int> seen;  // what the kills left
  for (int kill = 1; kill <= 55; ++kill) {
    const pid_t pid = Spawn(EveryFormatSet(out, kill), log);
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
    ::kill(pid, SIGKILL);
    const int status = WaitFor(pid, std::chrono::seconds(60));
    const std::string context = "kill " + std::to_string(kill);
    const size_t finals = ExpectOneRun(out, context, &temporaries);
    ++seen[std::string(WIFSIGNALED(status) ? "killed" : "finished") +
           (finals == kEveryFormatSetFiles ? ", whole set" : ", part of a set") +
           (temporaries > 0 ? ", temporaries" : "")];
    if (::testing::Test::HasFailure()) break;
  }
  // The next run in the same directory: succeeds, one whole set, nothing else.
  ASSERT_EQ(WaitFor(Spawn(EveryFormatSet(out, 99), log), std::chrono::seconds(60)), 0)
      << ReadAll(log);
  EXPECT_EQ(ExpectOneRun(out, "after the kills", &temporaries), kEveryFormatSetFiles);
  EXPECT_EQ(temporaries, 0u);
  EXPECT_NE(RunOf(out / "E.exr").find("--seed 99"), std::string::npos);
  std::string summary;
  for (const auto &[what, count] : seen)
    summary += "  " + what + ": " + std::to_string(count) + "\n";
  std::printf("one bake %.3f s; 55 kills left:\n%s", seconds, summary.c_str());
  fs::remove_all(out);
  fs::remove(log);
}

// The kills again on a preset bake (Cycles' 2D tables: two C arrays and
// preset.json, written as one set): preset.json always parses and names the run that
// wrote both arrays beside it. The runs differ by --threads, which changes
// nothing in the values but is recorded in the command line.
TEST(Reliability, KillsDuringAPresetBakeNeverLeaveAMixedSet) {
  const fs::path out = lutbake::test::Scratch("preset_kills");
  const fs::path log = out.string() + ".log";
  const auto run = [&](int threads) {
    return std::vector<std::string>{"bake",
                                    "--preset",
                                    "cycles",
                                    "--files",
                                    "table_ggx_E.h,table_ggx_Eavg.h",
                                    "--out",
                                    out.string(),
                                    "--threads",
                                    std::to_string(threads)};
  };
  // The final files (all of one run); *temporaries counts the rest.
  size_t temporaries = 0;
  const auto expectOneRun = [&](const std::string &context) {
    std::string recorded;
    size_t finals = 0;
    temporaries = 0;
    for (const auto &entry : fs::directory_iterator(out)) {
      const std::string name = entry.path().filename().string();
      if (lutbake::IsTemporaryName(name)) {
        ++temporaries;
        continue;
      }
      ++finals;
      std::string of;
      try {
        if (name == lutbake::kSetManifestName) {
          of = SetManifestRun(entry.path());
        } else if (name == "preset.json") {
          lutbake::ReadPresetListing(entry.path().string());  // whole JSON
          const std::string text = ReadAll(entry.path()), key = "\"commandLine\": \"";
          const size_t at = text.find(key);
          if (at != std::string::npos)
            of = text.substr(at + key.size(), text.find('"', at + key.size()) - at - key.size());
        } else {
          for (const auto &[k, v] : lutbake::ReadSourceTable(entry.path().string()).metadata)
            if (k == "commandLine") of = v;
        }
      } catch (const std::exception &e) {
        ADD_FAILURE() << context << ": " << name << " does not parse: " << e.what();
      }
      EXPECT_FALSE(of.empty()) << context << ": " << name << " records no command line";
      if (recorded.empty()) recorded = of;
      EXPECT_EQ(of, recorded) << context << ": " << name << " belongs to another run";
    }
    return finals;
  };
  const auto start = Clock::now();
  ASSERT_EQ(WaitFor(Spawn(run(1), log), std::chrono::seconds(60)), 0) << ReadAll(log);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  // Two C arrays, preset.json and lutbake-set.json.
  ASSERT_EQ(expectOneRun("first run"), 4u);
  std::mt19937 random(16);
  std::uniform_real_distribution<double> moment(0.0, 1.1 * seconds);
  for (int kill = 1; kill <= 20 && !::testing::Test::HasFailure(); ++kill) {
    const pid_t pid = Spawn(run(1 + kill % 16), log);
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
    ::kill(pid, SIGKILL);
    WaitFor(pid, std::chrono::seconds(60));
    // The directory held a whole set before: it holds one, old or new, or
    // (a kill within the commit's renames) part of one run's set, possibly
    // none of it, and the named temporaries the next run removes
    // (docs/reliability.md).
    const size_t finals = expectOneRun("kill " + std::to_string(kill));
    EXPECT_TRUE(finals == 4u || temporaries > 0u)
        << "kill " << kill << ": " << finals << " files, " << temporaries << " temporaries";
  }
  ASSERT_EQ(WaitFor(Spawn(run(2), log), std::chrono::seconds(60)), 0) << ReadAll(log);
  EXPECT_EQ(expectOneRun("after the kills"), 4u);
  EXPECT_EQ(temporaries, 0u) << "the next run removes the killed runs' temporaries";
  fs::remove_all(out);
  fs::remove(log);
}

// SIGINT into a new directory, SIGTERM over a previous set: exit 128 + the
// signal within a second, one line naming it, the directory as before.
TEST(Reliability, SigintAndSigtermEndPromptlyAndLeaveNothing) {
  for (const int signal : {SIGINT, SIGTERM}) {
    const std::string name = signal == SIGINT ? "SIGINT" : "SIGTERM";
    const fs::path out = lutbake::test::Scratch("signal_" + name);
    const fs::path log = out.string() + ".log";
    std::map<std::string, std::string> before;
    if (signal == SIGTERM) {
      ASSERT_EQ(WaitFor(Spawn(SmallSet(out, 1), log), std::chrono::seconds(60)), 0);
      before = Contents(out);
    }
    const pid_t pid = Spawn(LongBake(out), log);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(pid, signal);
    const auto sent = Clock::now();
    const int status = WaitFor(pid, std::chrono::seconds(30));
    const double latency = std::chrono::duration<double>(Clock::now() - sent).count();
    ASSERT_TRUE(status != -1 && WIFEXITED(status)) << name << ": " << ReadAll(log);
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal) << name << ": " << ReadAll(log);
    EXPECT_LT(latency, 1.0) << name;
    // One line about the signal. The large-request estimate may come
    // before it: it is printed when the bake, timed on a sample, would take
    // over 10 s, which a loaded machine can make this one.
    std::vector<std::string> lines = Lines(ReadAll(log));
    if (lines.size() == 2 && lines[0].find("texels, about") != std::string::npos)
      lines.erase(lines.begin());
    ASSERT_EQ(lines.size(), 1u) << ReadAll(log);
    EXPECT_EQ(lines[0],
              "lutbake bake: interrupted by " + name + "; nothing written to " + out.string());
    if (signal == SIGINT) {
      EXPECT_FALSE(fs::exists(out)) << "the directory the run created is left";
    } else {
      EXPECT_EQ(Contents(out), before) << "the previous set changed";
    }
    fs::remove_all(out);
    fs::remove(log);
  }
}

// `lutbake report` (a minute of bakes by default) ends on a signal as a bake
// does: during its reference values and later during its timed runs.
TEST(Reliability, ReportEndsOnSignalsLikeABake) {
  for (const int signal : {SIGINT, SIGTERM}) {
    for (const int afterMs : {200, 2500}) {
      const std::string name = signal == SIGINT ? "SIGINT" : "SIGTERM";
      const std::string context = name + " after " + std::to_string(afterMs) + " ms";
      const fs::path out = lutbake::test::Scratch("report_signal_" + name);
      const fs::path log = out.string() + ".log";
      const pid_t pid = Spawn({"report", "--out", out.string(), "--threads", "1"}, log);
      std::this_thread::sleep_for(std::chrono::milliseconds(afterMs));
      ::kill(pid, signal);
      const auto sent = Clock::now();
      const int status = WaitFor(pid, std::chrono::seconds(30));
      const double latency = std::chrono::duration<double>(Clock::now() - sent).count();
      ASSERT_TRUE(status != -1 && WIFEXITED(status)) << context << ": " << ReadAll(log);
      EXPECT_EQ(WEXITSTATUS(status), 128 + signal) << context << ": " << ReadAll(log);
      EXPECT_LT(latency, 1.0) << context;
      const std::vector<std::string> lines = Lines(ReadAll(log));
      ASSERT_EQ(lines.size(), 1u) << context << ": " << ReadAll(log);
      EXPECT_EQ(lines[0],
                "lutbake report: interrupted by " + name + "; nothing written to " + out.string());
      EXPECT_FALSE(fs::exists(out)) << context << ": the directory the run created is left";
      fs::remove_all(out);
      fs::remove(log);
    }
  }
}

// A file size limit that the first files fit and a later one does not:
// exit 1, the file and the reason, the previous set untouched.
TEST(Reliability, FileSizeLimitFailsWithTheFileAndReasonAndKeepsThePreviousSet) {
  const fs::path out = lutbake::test::Scratch("fsize");
  const fs::path log = out.string() + ".log";
  ASSERT_EQ(WaitFor(Spawn(SmallSet(out, 1), log), std::chrono::seconds(60)), 0);
  const auto before = Contents(out);
  // At size 64: E.exr (16.5 KiB, the first file written) fits in 24 KiB,
  // E.bin (33 KiB) does not. SIGXFSZ is at its default: lutbake must ignore
  // it itself.
  SpawnOptions limited;
  limited.fileSizeLimit = 24 * 1024;
  const int status = WaitFor(Spawn(SmallSet(out, 2, 64), log, limited), std::chrono::seconds(60));
  const std::string output = ReadAll(log);
  ASSERT_TRUE(status != -1 && WIFEXITED(status)) << "killed by signal: " << output;
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_NE(
      output.find("lutbake bake: cannot write " + (out / "E.bin").string() + ": File too large"),
      std::string::npos)
      << output;
  EXPECT_EQ(Contents(out), before) << "the previous set changed";
  ExpectNoTemporary(out, "file size limit");
  fs::remove_all(out);
  fs::remove(log);
}

// A full file system (a 256 KiB tmpfs; mounting needs CAP_SYS_ADMIN).
TEST(Reliability, FullDiskFailsWithTheFileAndReasonAndKeepsThePreviousSet) {
  const fs::path out = lutbake::test::Scratch("tmpfs");
  const fs::path log = out.string() + ".log";
  fs::create_directories(out);
  if (::mount("tmpfs", out.c_str(), "tmpfs", 0, "size=256k") != 0) {
    const std::string reason = std::strerror(errno);
    fs::remove_all(out);
    GTEST_SKIP() << "cannot mount a tmpfs (" << reason
                 << "); the file size limit test covers write errors";
  }
  ASSERT_EQ(WaitFor(Spawn(SmallSet(out, 1), log), std::chrono::seconds(60)), 0) << ReadAll(log);
  const auto before = Contents(out);
  const int status = WaitFor(Spawn(SmallSet(out, 2, 128), log), std::chrono::seconds(60));
  const std::string output = ReadAll(log);
  EXPECT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 1) << output;
  EXPECT_NE(output.find("lutbake bake: cannot write " + out.string() + "/"), std::string::npos)
      << output;
  EXPECT_NE(output.find(": No space left on device"), std::string::npos) << output;
  EXPECT_EQ(Contents(out), before) << "the previous set changed";
  ExpectNoTemporary(out, "full disk");
  ::umount(out.c_str());
  fs::remove_all(out);
  fs::remove(log);
}

// Whether the user nobody (65534) may execute `path`: asked in a child that
// has become nobody, since root's own access() answers yes to everything. A
// checkout under a directory closed to others (/root, mode 0700) says no.
bool NobodyMayExecute(const char *path) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const bool nobody =
        ::setgroups(0, nullptr) == 0 && ::setgid(65534) == 0 && ::setuid(65534) == 0;
    ::_exit(nobody && ::access(path, X_OK) == 0 ? 0 : 1);
  }
  int status = 0;
  return pid > 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

// The output directory made read-only (0555) while the bake runs. Root
// ignores permissions, so as root the bake runs as nobody (65534); where
// nobody cannot reach the binary (a checkout under /root) the test skips.
TEST(Reliability, DirectoryMadeReadOnlyDuringTheRunFailsAndLeavesNothing) {
  const fs::path out = lutbake::test::Scratch("readonly");
  const fs::path log = out.string() + ".log";
  SpawnOptions options;
  options.asNobody = ::geteuid() == 0;
  if (options.asNobody && !NobodyMayExecute(LUTBAKE_BINARY))
    GTEST_SKIP() << "the user nobody cannot execute " << LUTBAKE_BINARY
                 << " (a directory above it is closed to others)";
  fs::create_directories(out);
  if (options.asNobody && ::chown(out.c_str(), 65534, 65534) != 0)
    GTEST_SKIP() << "cannot hand the directory to nobody";
  const pid_t pid = Spawn(LongBake(out), log, options);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(::chmod(out.c_str(), 0555), 0);
  const int status = WaitFor(pid, std::chrono::seconds(60));
  const std::string output = ReadAll(log);
  EXPECT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 1) << output;
  EXPECT_NE(output.find("lutbake bake: cannot write " + (out / "dfg.exr").string() +
                        ": Permission denied"),
            std::string::npos)
      << output;
  EXPECT_TRUE(Contents(out).empty()) << "files left in the read-only directory";
  fs::remove_all(out);
  fs::remove(log);
}

// A large request says what it will cost before the work: dfg 4096 x 4096
// (16.8 M texels) gets one line with its texels, a time measured on a
// sample and its memory; ended by SIGTERM during the bake, nothing is left.
TEST(Reliability, LargeRequestEstimatesTimeAndMemoryFirst) {
  const fs::path out = lutbake::test::Scratch("large");
  const fs::path log = out.string() + ".log";
  const pid_t pid =
      Spawn({"bake", "--out", out.string(), "--tables", "dfg", "--size", "4096"}, log);
  // The estimate bakes 256 texels twice; the whole table takes minutes.
  std::this_thread::sleep_for(std::chrono::seconds(3));
  ::kill(pid, SIGTERM);
  const int status = WaitFor(pid, std::chrono::seconds(30));
  const std::string output = ReadAll(log);
  EXPECT_TRUE(status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << output;
  const std::vector<std::string> lines = Lines(output);
  ASSERT_EQ(lines.size(), 2u) << output;
  EXPECT_EQ(lines[0].rfind("lutbake bake: dfg: 16777216 texels, about ", 0), 0u) << output;
  EXPECT_NE(lines[0].find(" s on "), std::string::npos) << output;
  // 16777216 x (24 x 2 + 64) bytes = 1792 MiB.
  EXPECT_NE(lines[0].find("about 1792 MiB of memory"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(log);
}

}  // namespace
