// The lutbake executable: bad input is refused with exit 2 (usage) or 1
// (cannot write) and leaves nothing behind; output does not depend on --threads.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/output_transaction.h"
#include "support/cli_run.h"

namespace {

namespace fs = std::filesystem;

using lutbake::test::CommandResult;
using lutbake::test::Lutbake;
using lutbake::test::Scratch;

struct BadInput {
  std::string args, mentions;
};

TEST(Cli, BadInputIsRefusedWithUsageStatusAndNoOutput) {
  const fs::path out = Scratch("bad");
  for (const BadInput &bad : std::vector<BadInput>{{"--size 0", "--size"},
                                                   {"--size 100000", "4096"},
                                                   {"--samples 0", "--samples"},
                                                   {"--samples -3", "--samples"},
                                                   {"--ndf foo", "ggx, beckmann"},
                                                   {"--smith tall", "correlated"},
                                                   {"--tables E,nope", "nope"},
                                                   {"--format exr,png", "png"},
                                                   {"--threads 0", "--threads"},
                                                   {"--namespace 9bad", "namespace"},
                                                   {"--tolerance 0", "1e-9 to 0.1"},
                                                   {"--tolerance abc", "not a number"},
                                                   {"--tolerance nan", "not a number"},
                                                   {"--estimator magic", "vndf-random"},
                                                   {"--replicates 1", "--replicates"},
                                                   {"--sampling-only", "--tolerance"},
                                                   {"--frobnicate", "frobnicate"}}) {
    const CommandResult r = Lutbake("bake --out " + out.string() + " " + bad.args);
    EXPECT_EQ(r.status, 2) << bad.args << ": " << r.output;
    EXPECT_NE(r.output.find(bad.mentions), std::string::npos) << bad.args << ": " << r.output;
    EXPECT_FALSE(fs::exists(out)) << bad.args;
  }
  EXPECT_EQ(Lutbake("bake").status, 2);  // --out is required
}

TEST(Cli, OutThatIsAFileOrUnwritable) {
  const fs::path file = Scratch("file");
  std::ofstream(file) << "not a directory";
  const CommandResult r = Lutbake("bake --out " + file.string() + " --size 2 --samples 2");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(file.string()), std::string::npos);
  fs::remove(file);
  // A directory that cannot be created (its parent is a file).
  std::ofstream(file) << "x";
  const CommandResult r2 =
      Lutbake("bake --out " + (file / "sub").string() + " --size 2 --samples 2");
  EXPECT_EQ(r2.status, 1) << r2.output;
  fs::remove(file);
}

TEST(Cli, HelpListsEveryOption) {
  const CommandResult r = Lutbake("bake --help");
  EXPECT_EQ(r.status, 0);
  for (const char *flag : {"--out", "--tables", "--ndf", "--smith", "--fresnel", "--size",
                           "--samples", "--seed", "--threads", "--format", "--json", "Example"})
    EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
  EXPECT_EQ(Lutbake("--help").status, 0);
}

// docs/cli.md: --version and help on every command, -o for --out, -q.
TEST(Cli, EveryCommandTakesVersionAndHelp) {
  const std::string version = Lutbake("--version").output;
  ASSERT_NE(version.find("lutbake "), std::string::npos) << version;
  for (const char *command : {"bake", "plan", "eval", "check", "report", "furnace", "presets"}) {
    const CommandResult r = Lutbake(std::string(command) + " --version");
    EXPECT_EQ(r.status, 0) << command << ": " << r.output;
    EXPECT_EQ(r.output, version) << command;
    const CommandResult help = Lutbake(std::string("help ") + command);
    EXPECT_EQ(help.status, 0) << command;
    EXPECT_EQ(help.output, Lutbake(std::string(command) + " --help").output) << command;
    // At 80 columns, the types plain ("--ndf NAME", not "TEXT:one of: ...").
    std::stringstream lines(help.output);
    for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 80u) << line;
    for (const char *raw : {"TEXT", ":one of", ":comma-separated", "float64 keeps"})
      EXPECT_EQ(help.output.find(raw), std::string::npos) << command << ": " << raw;
  }
  EXPECT_EQ(Lutbake("help").output, Lutbake("--help").output);
  const CommandResult unknown = Lutbake("help bak");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.output.find("did you mean bake?"), std::string::npos) << unknown.output;
}

TEST(Cli, ShortOutAndQuiet) {
  const fs::path out = Scratch("short_out"), quiet = Scratch("quiet");
  const CommandResult r = Lutbake("bake -o " + out.string() + " --tables E --size 2 --samples 64");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "E.exr"));
  EXPECT_NE(r.output.find("error max"), std::string::npos) << r.output;
  const CommandResult q =
      Lutbake("bake -q -o " + quiet.string() + " --tables E --size 2 --samples 64");
  EXPECT_EQ(q.status, 0) << q.output;
  EXPECT_TRUE(fs::exists(quiet / "E.exr"));
  EXPECT_EQ(q.output, "");
  // Errors are still printed.
  const CommandResult bad = Lutbake("bake -q -o " + quiet.string() + " --tables nope");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("'nope'"), std::string::npos);
  fs::remove_all(out);
  fs::remove_all(quiet);
}

// -v: the equivalent command line first, then a line per file written with
// its format and stated bound; -v with -q is refused.
TEST(Cli, VerboseListsEveryFileWithItsBound) {
  const fs::path out = Scratch("verbose");
  const CommandResult r =
      Lutbake("bake -v -o " + out.string() + " --tables E --size 4 --format exr,header");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("lutbake bake: lutbake bake --out " + out.string() +
                               " --tables E --format exr,header --size 4\n",
                           0),
            0u)
      << r.output;
  for (const char *file : {"E.exr", "E.h"}) {
    const size_t at = r.output.find("\n  " + std::string(file) + " ");
    ASSERT_NE(at, std::string::npos) << file << "\n" << r.output;
    const std::string line = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find("error max "), std::string::npos) << line;
  }
  const CommandResult both = Lutbake("bake -v -q -o " + out.string() + " --tables E --size 4");
  EXPECT_EQ(both.status, 2) << both.output;
  EXPECT_NE(both.output.find("--quiet excludes --verbose"), std::string::npos) << both.output;
  fs::remove_all(out);
}

std::string ReadFile(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Bakes with `options` at each thread count (written with two digits, so
// that every recorded command line has the same length) and compares every
// file byte for byte, the command lines blanked out.
void ExpectSameFilesForThreadCounts(const std::string &options, int files) {
  std::vector<fs::path> dirs;
  std::vector<std::string> args;
  for (const char *threads : {"01", "02", "16"}) {
    dirs.push_back(Scratch(std::string("t") + threads));
    args.push_back(dirs.back().string() + " " + options + " --threads " + threads);
    ASSERT_EQ(Lutbake("bake --out " + args.back()).status, 0) << args.back();
  }
  int compared = 0;
  for (const auto &entry : fs::directory_iterator(dirs[0])) {
    const std::string name = entry.path().filename().string();
    if (lutbake::IsTemporaryName(name) || name.find(".tmp") != std::string::npos)
      ADD_FAILURE() << "temporary left: " << name;
    std::vector<std::string> contents;
    for (const fs::path &dir : dirs) {
      ASSERT_TRUE(fs::exists(dir / name)) << name;
      std::string text = ReadFile(dir / name);
      for (const std::string &arg : args)
        for (size_t at = text.find(arg); at != std::string::npos; at = text.find(arg))
          text.replace(at, arg.size(), std::string(arg.size(), '#'));
      contents.push_back(text);
    }
    for (size_t k = 1; k < contents.size(); ++k) EXPECT_EQ(contents[k], contents[0]) << name;
    if (name != lutbake::kSetManifestName) ++compared;  // compared, not counted
  }
  EXPECT_EQ(compared, files);
  for (const fs::path &dir : dirs) fs::remove_all(dir);
}

TEST(Cli, OutputIsByteIdenticalForOneTwoAndSixteenThreads) {
  // The default bake (quadrature), with the error maps and a float64 .bin;
  // and the sampled one. 4 tables x (exr, bin, h), kulla_conty.h, and for
  // the first the 4 error maps.
  ExpectSameFilesForThreadCounts("--size 8 --error-map --bin-type double", 17);
  ExpectSameFilesForThreadCounts("--size 8 --samples 128", 13);
}

TEST(Cli, JsonSummary) {
  const fs::path out = Scratch("json");
  const CommandResult r = Lutbake("bake --out " + out.string() +
                                  " --tables Favg,E --size 4 --samples 16 --format bin --json");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("\"name\": \"Favg\""), std::string::npos);
  EXPECT_NE(r.output.find("\"errorMax\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "E.bin"));
  EXPECT_FALSE(fs::exists(out / "E.exr"));
  fs::remove_all(out);
}

}  // namespace

namespace {

TEST(Cli, ErrorMapHasTheTableLayoutAndItsBounds) {
  const fs::path out = Scratch("errmap");
  const CommandResult r = Lutbake("bake --out " + out.string() +
                                  " --tables dfg --size 4 --samples 64 --error-map "
                                  "--format exr");
  ASSERT_EQ(r.status, 0) << r.output;
  auto image = OIIO::ImageInput::open((out / "dfg.err.exr").string());
  ASSERT_TRUE(image);
  const OIIO::ImageSpec &spec = image->spec();
  EXPECT_EQ(spec.width, 4);
  EXPECT_EQ(spec.height, 4);
  EXPECT_EQ(spec.nchannels, 2);
  std::vector<float> errors(32);
  ASSERT_TRUE(image->read_image(0, 0, 0, 2, OIIO::TypeDesc::FLOAT, errors.data()));
  // Each texel's bound is at least the unseen-event term 4.6 / 64 and positive.
  for (float e : errors) EXPECT_GE(e, 4.6f / 64.0f);
  EXPECT_NE(spec.get_string_attribute("content").find("error bound"), std::string::npos);
  fs::remove_all(out);
}

TEST(Cli, ToleranceRunReportsWhatItReached) {
  const fs::path out = Scratch("tol");
  const CommandResult r = Lutbake("bake --out " + out.string() +
                                  " --tables E --size 4 --tolerance 1e-5 --json --format bin");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("tolerance 1e-05 reached on every texel"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"quadratureTexels\": 16"), std::string::npos) << r.output;
  fs::remove_all(out);
  // Sampling alone, capped below what 1e-5 needs: refused, nothing written.
  const CommandResult capped =
      Lutbake("bake --out " + out.string() +
              " --tables E --size 2 --tolerance 1e-5 --sampling-only --max-samples 1024");
  EXPECT_EQ(capped.status, 1) << capped.output;
  EXPECT_NE(capped.output.find("--max-samples"), std::string::npos) << capped.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, ReportWritesCsvMarkdownAndSvg) {
  const fs::path out = Scratch("report");
  const CommandResult r = Lutbake("report --out " + out.string() +
                                  " --tables E --estimators vndf,quadrature --size 4 --budget 1");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char *name : {"report.csv", "report.md", "report.svg"})
    EXPECT_GT(fs::file_size(out / name), 100u) << name;
  std::ifstream csv(out / "report.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("table,estimator,samples_per_texel", 0), 0u) << header;
  const CommandResult bad = Lutbake("report --out " + out.string() + " --tables Favg");
  EXPECT_EQ(bad.status, 2) << bad.output;
  fs::remove_all(out);
}

}  // namespace
