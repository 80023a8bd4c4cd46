// Source embeddings (--format inc, inc-half, js, js-half, ts, ts-half,
// glsl-array, hlsl-array, wgsl-array, msl-array): every value read back at
// its storage precision (float32 bit for bit; half as the binary16 nearest
// to the float32 value, ties to even), the metadata each file states
// (axes, errorMax of its storage), the ES module evaluated by node, and
// CheckBakedSet (`lutbake check`) holding each to its storage.
#include "lutbake/formats/source_formats.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/lutbake.h"
#include "lutbake/tables/storage.h"
#include "lutbake/validation/check.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

struct Embedding {
  const char *format;
  ValueType storage;
};

const Embedding kEmbeddings[] = {
    {"inc", ValueType::kFloat32},        {"inc-half", ValueType::kHalf},
    {"js", ValueType::kFloat32},         {"js-half", ValueType::kHalf},
    {"ts", ValueType::kFloat32},         {"ts-half", ValueType::kHalf},
    {"glsl-array", ValueType::kFloat32}, {"hlsl-array", ValueType::kFloat32},
    {"wgsl-array", ValueType::kFloat32}, {"msl-array", ValueType::kFloat32},
};

std::string ReadText(const fs::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SourceFormats, ValuesRoundTripAtTheirStoragePrecision) {
  const fs::path dir = test::FormatTempDir("source");
  const std::vector<std::pair<std::string, Table>> tables = {
      {"E", test::SmallTableOf(TableNamed("E"))},
      {"dfg", test::SmallTableOf(TableNamed("dfg"))},
      {"Eavg", test::SmallTableOf(TableNamed("Eavg"))},
      {"E3d", test::ThreeSliceTable()},
  };
  for (const Embedding &e : kEmbeddings)
    for (const auto &[label, table] : tables) {
      SCOPED_TRACE(std::string(e.format) + " " + label);
      const std::unique_ptr<TableWriter> writer = MakeWriter(e.format);
      ASSERT_NE(writer, nullptr);
      EXPECT_EQ(writer->formatName(), std::string(e.format));
      const std::string path = (dir / (label + writer->extension())).string();
      writer->Write(table, path, {});
      const Table back = ReadSourceTable(path);
      EXPECT_EQ(DescribeAxis(back.x), DescribeAxis(table.x));
      EXPECT_EQ(DescribeAxis(back.y), DescribeAxis(table.y));
      EXPECT_EQ(DescribeAxis(back.z), DescribeAxis(table.z));
      EXPECT_EQ(back.channels, table.channels);
      EXPECT_EQ(*back.FindMetadata("errorStorage"), ToString(e.storage));
      EXPECT_EQ(*back.FindMetadata("errorMax"),
                FormatDouble(SummarizeStoredBounds(table, e.storage).max));
      EXPECT_EQ(*back.FindMetadata("table"), *table.FindMetadata("table"));
      ASSERT_EQ(back.values.size(), table.values.size());
      for (size_t i = 0; i < table.values.size(); ++i)
        ASSERT_EQ(back.values[i], StoredValue(table.values[i], e.storage)) << i;
    }
}

// Half storage rounds the float32 value to the nearest binary16, ties to
// even: 1 + 2^-11 lies half-way between 1 (0x3c00, even) and 1 + 2^-10
// (0x3c01) and goes to 0x3c00; 1 + 3 2^-11 half-way between 0x3c01 and
// 0x3c02 goes to 0x3c02; 1 + 2^-11 + 2^-20 is above the tie: 0x3c01.
TEST(SourceFormats, HalfRoundsToNearestEven) {
  Table t = test::SmallTableOf(TableNamed("Eavg"), 4);
  t.values = {1.0 + 0x1p-11, 1.0 + 3 * 0x1p-11, 1.0 + 0x1p-11 + 0x1p-20, 0.25};
  const fs::path dir = test::FormatTempDir("source_half");
  for (const char *format : {"inc-half", "js-half", "ts-half"}) {
    SCOPED_TRACE(format);
    const std::unique_ptr<TableWriter> writer = MakeWriter(format);
    const fs::path path = dir / (std::string("Eavg") + writer->extension());
    writer->Write(t, path.string(), {});
    const std::string text = ReadText(path);
    EXPECT_NE(text.find("0x3c00, 0x3c02, 0x3c01, 0x3400"), std::string::npos) << text;
    const Table back = ReadSourceTable(path.string());
    EXPECT_EQ(back.values, (std::vector<double>{1.0, 1.0 + 0x1p-9, 1.0 + 0x1p-10, 0.25}));
  }
}

TEST(SourceFormats, ReaderRejectsAMissingValue) {
  const fs::path dir = test::FormatTempDir("source_cut");
  const fs::path path = dir / "E.inc";
  MakeWriter("inc")->Write(test::SmallTableOf(TableNamed("E")), path.string(), {});
  std::string text = ReadText(path);
  const size_t end = text.find("// lutbake-values-end");
  const size_t comma = text.rfind(',', end);  // every literal of an .inc ends with one
  const size_t start = text.rfind(' ', comma);
  text.erase(start, comma + 1 - start);  // drops the last literal
  std::ofstream(path) << text;
  EXPECT_THROW(ReadSourceTable(path.string()), IoError);
}

using test::RunCommand;

// The ES module as node imports it: the exports, and every typed-array
// element (Float32Array: the float32 value; Uint16Array: the binary16 bits).
TEST(SourceFormats, NodeImportsTheEsModule) {
  if (std::system("command -v node >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "node not found: the ES modules are not imported here (scripts/setup.sh "
                    "installs nodejs)";
  const fs::path dir = test::FormatTempDir("source_node");
  const Table t = test::ThreeSliceTable();
  for (const char *format : {"js", "js-half"}) {
    SCOPED_TRACE(format);
    const bool half = std::string(format) == "js-half";
    const fs::path sub = dir / format;
    fs::create_directories(sub);
    MakeWriter(format)->Write(t, (sub / "E.mjs").string(), {});
    std::ofstream(sub / "dump.mjs")
        << "import m, { data, axes } from './E.mjs';\n"
           "console.log(JSON.stringify({ table: m.table, width: m.width, height: m.height,\n"
           "  depth: m.depth, channels: m.channels, storage: m.storage, errorMax: m.errorMax,\n"
           "  kind: data.constructor.name, axes, data: Array.from(data) }));\n";
    int status = 0;
    const std::string out = RunCommand("node '" + (sub / "dump.mjs").string() + "' 2>&1", &status);
    ASSERT_EQ(status, 0) << out;
    const nlohmann::json j = nlohmann::json::parse(out);
    EXPECT_EQ(j["table"], "E");
    EXPECT_EQ(j["width"], t.width());
    EXPECT_EQ(j["height"], t.height());
    EXPECT_EQ(j["depth"], t.depth());
    EXPECT_EQ(j["channels"], 1);
    EXPECT_EQ(j["storage"], half ? "half" : "float32");
    EXPECT_EQ(j["kind"], half ? "Uint16Array" : "Float32Array");
    EXPECT_EQ(j["errorMax"].get<double>(),
              std::stod(FormatDouble(
                  SummarizeStoredBounds(t, half ? ValueType::kHalf : ValueType::kFloat32).max)));
    ASSERT_EQ(j["axes"].size(), 3u);
    EXPECT_EQ(j["axes"][2]["name"], "eta");
    EXPECT_EQ(j["axes"][2]["count"], 3);
    ASSERT_EQ(j["data"].size(), t.values.size());
    for (size_t i = 0; i < t.values.size(); ++i) {
      if (half)
        ASSERT_EQ(j["data"][i].get<unsigned>(), Imath::half(static_cast<float>(t.values[i])).bits())
            << i;
      else
        ASSERT_EQ(j["data"][i].get<double>(), static_cast<float>(t.values[i])) << i;
    }
  }
}

// Bake writes every embedding and CheckBakedSet holds each to
// its storage ("texture formats"); one literal moved by a float32 ulp fails;
// an embedding alone is checked as the primary file.
TEST(SourceFormats, CheckHoldsEachEmbeddingToItsStorage) {
  const fs::path d = test::Scratch("check_sources");
  BakeRequest request = test::BakeRequestFor(d);
  request.tables = {"E", "Eavg", "dfg"};
  request.size = 8;
  request.sampling.tolerance = 1e-6;
  request.formats = {"exr",        "inc-half",   "js",         "ts-half",
                     "glsl-array", "hlsl-array", "wgsl-array", "msl-array"};
  Bake(request);
  CheckOptions quick;
  quick.randomPoints = 32;
  quick.furnaceGrid = 65;
  CheckReport r = CheckBakedSet(d.string(), quick);
  EXPECT_TRUE(r.passed());
  const auto find = [](const CheckReport &report, const std::string &subject) {
    for (const CheckResult &c : report.results)
      if (c.subject == subject && c.check == "texture formats") return &c;
    return static_cast<const CheckResult *>(nullptr);
  };
  const CheckResult *textures = find(r, "dfg");
  ASSERT_NE(textures, nullptr);
  EXPECT_EQ(textures->status, CheckStatus::kPass);
  for (const char *file :
       {"dfg.inc (half)", "dfg.js (float32)", "dfg.ts (half)", "dfg.glsl (float32)",
        "dfg.hlsl (float32)", "dfg.wgsl (float32)", "dfg.metal (float32)"})
    EXPECT_NE(textures->detail.find(file), std::string::npos) << file << ": " << textures->detail;
  // The first literal of dfg.wgsl one float32 ulp up.
  const fs::path wgsl = d / "dfg.wgsl";
  std::string text = ReadText(wgsl);
  const size_t at = text.find("// lutbake-values-begin\n") + 24;
  const size_t comma = text.find(',', at);
  const float first = std::strtof(text.c_str() + at, nullptr);
  char moved[48];
  std::snprintf(moved, sizeof moved, "    %.9g", static_cast<double>(std::nextafter(first, 2.0f)));
  text.replace(at, comma - at, moved);
  std::ofstream(wgsl) << text;
  r = CheckBakedSet(d.string(), quick);
  textures = find(r, "dfg");
  ASSERT_NE(textures, nullptr);
  EXPECT_EQ(textures->status, CheckStatus::kFail);
  EXPECT_NE(textures->detail.find("dfg.wgsl differs at texel (0, 0) channel 0"), std::string::npos)
      << textures->detail;
  // An embedding alone.
  const fs::path alone = test::Scratch("check_sources_alone");
  BakeRequest single = test::BakeRequestFor(alone);
  single.tables = {"E", "Eavg"};
  single.size = 8;
  single.sampling.tolerance = 1e-6;
  single.formats = {"js-half"};
  Bake(single);
  r = CheckBakedSet(alone.string(), quick);
  EXPECT_TRUE(r.passed());
  fs::remove_all(d);
  fs::remove_all(alone);
}

}  // namespace
}  // namespace lutbake
