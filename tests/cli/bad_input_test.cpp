// The bad-input corpus (tests/data/bad_inputs.tsv): every case is an
// argument line that lutbake must refuse with its exit status (2 usage, 1
// runtime), a message on stderr that names the offending input and what is
// accepted, nothing on stdout (but check's report), and no file written
// anywhere it could write.
//
// Each case runs with a fresh, empty scratch directory as its working
// directory; {out} is a directory inside it that does not exist. After the
// run the scratch directory must still be empty (no --out created, no file
// in the working directory), and the shared fixtures must be unchanged.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct BadInputCase {
  int line = 0;
  int status = 0;
  std::string args;
  std::vector<std::string> mentions;
};

// How ctest and failures name a case: its line and arguments.
void PrintTo(const BadInputCase &c, std::ostream *os) {
  *os << "line " << c.line << ": " << c.args;
}

// Lines of the corpus: "STATUS<TAB>ARGS<TAB>MENTION<TAB>MENTION...", '#'
// starts a comment line. ARGS is a shell word list.
std::vector<BadInputCase> LoadCorpus() {
  std::ifstream in(std::string(LUTBAKE_TEST_DATA) + "/bad_inputs.tsv");
  std::vector<BadInputCase> cases;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, '\t');) fields.push_back(field);
    BadInputCase c;
    c.line = number;
    c.status = fields.empty() ? -1 : std::atoi(fields[0].c_str());
    if (fields.size() > 1) c.args = fields[1];
    c.mentions.assign(fields.begin() + std::min<size_t>(2, fields.size()), fields.end());
    cases.push_back(c);
  }
  return cases;
}

const std::vector<BadInputCase> &Corpus() {
  static const std::vector<BadInputCase> cases = LoadCorpus();
  return cases;
}

std::string Subcommand(const BadInputCase &c) {
  const std::string word = c.args.substr(0, c.args.find(' '));
  return word.empty() || word[0] == '-' ? "none" : word;
}

std::string ReadFile(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Every path under dir with its size and contents, to see that nothing
// changed.
std::map<std::string, std::string> Snapshot(const fs::path &dir) {
  std::map<std::string, std::string> files;
  for (const auto &entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(entry.path(), dir).string();
    files[name] = entry.is_regular_file() ? ReadFile(entry.path()) : std::string("<dir>");
  }
  return files;
}

int RunShell(const std::string &command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// Files the cases refer to as {fixtures}/...: made once per process.
class BadInput : public testing::TestWithParam<BadInputCase> {
 protected:
  static void SetUpTestSuite() {
    fixtures_ =
        fs::temp_directory_path() / ("lutbake_bad_input_fixtures_" + std::to_string(::getpid()));
    fs::remove_all(fixtures_);
    fs::create_directories(fixtures_ / "scene_dir.gltf");
    fs::create_directories(fixtures_ / "empty_dir");
    std::ofstream(fixtures_ / "regular.txt") << "a regular file, not a directory\n";
    std::ofstream(fixtures_ / "empty.gltf");
    std::ofstream(fixtures_ / "empty.json");
    // A bake whose Eavg.bin is cut in half.
    const fs::path truncated = fixtures_ / "truncated";
    ASSERT_EQ(RunShell(std::string(LUTBAKE_BINARY) + " bake --out " + truncated.string() +
                       " --tables Eavg --size 4 --format bin 2>/dev/null"),
              0);
    const fs::path bin = truncated / "Eavg.bin";
    fs::resize_file(bin, fs::file_size(bin) / 2);
    // A .bin that is not one at all.
    fs::create_directories(fixtures_ / "garbage");
    std::ofstream(fixtures_ / "garbage" / "E.bin") << "this is not a lutbake table";
    // Preset directories whose preset.json cannot be used.
    fs::create_directories(fixtures_ / "preset_not_json");
    std::ofstream(fixtures_ / "preset_not_json" / "preset.json") << "{\"preset\": \"cycles\", ";
    fs::create_directories(fixtures_ / "preset_foreign_file");
    std::ofstream(fixtures_ / "preset_foreign_file" / "preset.json")
        << R"({"preset": "cycles", "files": [{"file": "dfg.ktx2", "errorMax": 1e-7}]})";
    fs::create_directories(fixtures_ / "preset_no_file");
    std::ofstream(fixtures_ / "preset_no_file" / "preset.json")
        << R"({"preset": "godot", "files": []})";
    fs::create_directories(fixtures_ / "preset_unknown");
    std::ofstream(fixtures_ / "preset_unknown" / "preset.json")
        << R"({"preset": "quake", "files": [{"file": "dfg.ktx2", "errorMax": 1e-7}]})";
    before_ = Snapshot(fixtures_);
  }
  static void TearDownTestSuite() { fs::remove_all(fixtures_); }

  static fs::path fixtures_;
  static std::map<std::string, std::string> before_;
};

fs::path BadInput::fixtures_;
std::map<std::string, std::string> BadInput::before_;

std::string Expand(std::string text, const std::map<std::string, std::string> &values) {
  // {listN}: N comma-separated values 0.5 (lists too long to write out).
  static const std::regex list(R"(\{list([0-9]+)\})");
  for (std::smatch m; std::regex_search(text, m, list);) {
    std::string values05;
    for (int i = 0; i < std::stoi(m[1]); ++i) values05 += (i ? ",0.5" : "0.5");
    text.replace(m.position(0), m.length(0), values05);
  }
  for (const auto &[key, value] : values)
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
      text.replace(at, key.size(), value), at += value.size();
  return text;
}

TEST_P(BadInput, IsRefusedNamingTheInputAndWritingNothing) {
  const BadInputCase &c = GetParam();
  const fs::path scratch =
      fs::temp_directory_path() /
      ("lutbake_bad_input_" + std::to_string(::getpid()) + "_" + std::to_string(c.line));
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  const std::map<std::string, std::string> values = {{"{out}", (scratch / "out").string()},
                                                     {"{data}", LUTBAKE_TEST_DATA},
                                                     {"{fixtures}", fixtures_.string()}};
  const std::string args = Expand(c.args, values);
  const fs::path log = scratch.string() + ".log";
  // timeout: a case that hangs fails (124) instead of stopping the suite.
  const std::string command = "cd '" + scratch.string() + "' && timeout 60 " + LUTBAKE_BINARY +
                              " " + args + " >" + log.string() + ".out 2>" + log.string() + ".err";
  const int status = RunShell(command);
  const std::string out = ReadFile(log.string() + ".out");
  const std::string err = ReadFile(log.string() + ".err");
  fs::remove(log.string() + ".out");
  fs::remove(log.string() + ".err");
  SCOPED_TRACE("line " + std::to_string(c.line) + ": lutbake " + args + "\nstderr: " + err);

  EXPECT_EQ(status, c.status);
  EXPECT_FALSE(err.empty());
  // check prints its report on stdout, the failed checks included; every
  // other refusal prints nothing there.
  if (Subcommand(c) != "check") {
    EXPECT_TRUE(out.empty()) << "stdout: " << out;
  }
  ASSERT_FALSE(c.mentions.empty()) << "a case must say what its message names";
  for (const std::string &mention : c.mentions)
    EXPECT_NE(err.find(Expand(mention, values)), std::string::npos)
        << "the message does not mention '" << Expand(mention, values) << "'";
  std::vector<std::string> left;
  for (const auto &entry : fs::recursive_directory_iterator(scratch))
    left.push_back(fs::relative(entry.path(), scratch).string());
  EXPECT_TRUE(left.empty()) << "written: " << testing::PrintToString(left);
  EXPECT_EQ(Snapshot(fixtures_), before_) << "the fixtures changed";
  EXPECT_FALSE(fs::exists("/proc/lutbake_bad_input"));
  fs::remove_all(scratch);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, testing::ValuesIn(Corpus()),
                         [](const testing::TestParamInfo<BadInputCase> &info) {
                           char name[16];
                           std::snprintf(name, sizeof name, "L%03d_", info.param.line);
                           return name + Subcommand(info.param);
                         });

// The corpus itself: at least 60 cases, every subcommand, both statuses,
// every line well formed.
TEST(BadInputCorpus, CoversEverySubcommandWithSixtyCases) {
  const std::vector<BadInputCase> &cases = Corpus();
  EXPECT_GE(cases.size(), 60u);
  std::map<std::string, int> per;
  std::set<int> statuses;
  for (const BadInputCase &c : cases) {
    ++per[Subcommand(c)];
    statuses.insert(c.status);
    EXPECT_TRUE(c.status == 1 || c.status == 2) << "line " << c.line;
    EXPECT_FALSE(c.args.empty()) << "line " << c.line;
    EXPECT_FALSE(c.mentions.empty()) << "line " << c.line;
  }
  for (const char *command : {"bake", "plan", "check", "eval", "report", "furnace"})
    EXPECT_GE(per[command], 4) << command;
  EXPECT_EQ(statuses, (std::set<int>{1, 2}));
}

}  // namespace
