// KTX2 tables (--format ktx2, ktx2-half), parsed by a reader lutbake did not
// write: the npm package ktx-parse (pinned, installed under the build tree
// on first use; the test skips only when node or npm is missing) through
// tests/formats/ktx2_dump.mjs. Header, data format descriptor, key/value
// data and every texel are compared with what the KTX 2.0 specification
// asks for and with the table; lutbake's own reader (for `check`) too.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/storage.h"
#include "support/cli_run.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::FormatTempDir;

constexpr const char *kKtxParse = "ktx-parse@2.0.0";

using test::RunCommand;

struct Case {
  std::string name;
  Table table;
  ValueType storage;
  uint32_t vkFormat;
};

TEST(Ktx2Table, IndependentParserReadsHeaderDfdKeysAndTexels) {
  if (std::system("command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "node or npm not found: the KTX2 files are not checked by ktx-parse here "
                    "(scripts/setup.sh installs nodejs and npm)";
  const fs::path npm = fs::path(LUTBAKE_BUILD_DIR) / "npm";
  const fs::path modules = npm / "node_modules";
  int status = 0;
  if (!fs::exists(modules / "ktx-parse" / "package.json")) {
    const std::string log = RunCommand(
        "npm install --no-audit --no-fund --prefix '" + npm.string() + "' " + kKtxParse + " 2>&1",
        &status);
    ASSERT_EQ(status, 0) << "npm install " << kKtxParse << " failed:\n" << log;
  }
  const fs::path dir = FormatTempDir("ktx2");
  const std::vector<Case> cases = {
      {"E", test::SmallTableOf(TableNamed("E")), ValueType::kFloat32, 100},
      {"dfg", test::SmallTableOf(TableNamed("dfg")), ValueType::kFloat32, 103},
      {"E_half", test::SmallTableOf(TableNamed("E")), ValueType::kHalf, 76},
      {"dfg_half", test::SmallTableOf(TableNamed("dfg")), ValueType::kHalf, 83},
      {"E3d", test::ThreeSliceTable(), ValueType::kFloat32, 100},
      {"E3d_half", test::ThreeSliceTable(), ValueType::kHalf, 76},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.name);
    const Table &t = c.table;
    const std::string path = (dir / (c.name + ".ktx2")).string();
    MakeKtx2Writer(c.storage)->Write(t, path, {});
    const std::string out =
        RunCommand("node '" + std::string(LUTBAKE_TEST_DATA) + "/../formats/ktx2_dump.mjs' '" +
                       modules.string() + "' '" + path + "' 2>&1",
                   &status);
    ASSERT_EQ(status, 0) << out;
    const nlohmann::json k = nlohmann::json::parse(out);
    const int typeSize = c.storage == ValueType::kHalf ? 2 : 4;
    EXPECT_EQ(k["vkFormat"], c.vkFormat);
    EXPECT_EQ(k["typeSize"], typeSize);
    EXPECT_EQ(k["pixelWidth"], t.width());
    EXPECT_EQ(k["pixelHeight"], t.height());
    EXPECT_EQ(k["pixelDepth"], t.is3D() ? t.depth() : 0);
    EXPECT_EQ(k["layerCount"], 0);
    EXPECT_EQ(k["faceCount"], 1);
    EXPECT_EQ(k["levelCount"], 1);
    EXPECT_EQ(k["supercompressionScheme"], 0);
    // The basic data format descriptor of an SFLOAT format.
    const nlohmann::json &dfd = k["dfd"];
    EXPECT_EQ(dfd["vendorId"], 0);
    EXPECT_EQ(dfd["descriptorType"], 0);
    EXPECT_EQ(dfd["versionNumber"], 2);
    EXPECT_EQ(dfd["colorModel"], 1);        // KHR_DF_MODEL_RGBSDA
    EXPECT_EQ(dfd["colorPrimaries"], 1);    // BT709
    EXPECT_EQ(dfd["transferFunction"], 1);  // LINEAR
    EXPECT_EQ(dfd["texelBlockDimension"], nlohmann::json({0, 0, 0, 0}));
    EXPECT_EQ(dfd["bytesPlane"][0], typeSize * t.channels);
    ASSERT_EQ(dfd["samples"].size(), static_cast<size_t>(t.channels));
    for (int ch = 0; ch < t.channels; ++ch) {
      const nlohmann::json &s = dfd["samples"][ch];
      EXPECT_EQ(s["bitOffset"], ch * typeSize * 8);
      EXPECT_EQ(s["bitLength"], typeSize * 8 - 1);
      EXPECT_EQ(s["channelType"], ch | 0x80 | 0x40);  // R or G, FLOAT, SIGNED
      EXPECT_EQ(s["sampleLower"], 0xBF800000u);       // -1.0f
      EXPECT_EQ(s["sampleUpper"], 0x3F800000u);       // 1.0f
    }
    // Key/value data: the writer, the orientation and lutbake's metadata,
    // whose errorMax is the bound of the stored values.
    const nlohmann::json &kv = k["keyValue"];
    EXPECT_EQ(kv["KTXwriter"].get<std::string>().rfind("lutbake ", 0), 0u);
    EXPECT_EQ(kv["KTXorientation"], t.is3D() ? "rdi" : "rd");
    const nlohmann::json meta = nlohmann::json::parse(kv["lutbake.metadata"].get<std::string>());
    EXPECT_EQ(meta["table"], "E" == c.name.substr(0, 1) ? "E" : "dfg");
    EXPECT_EQ(meta["axisX"], *t.FindMetadata("axisX"));
    EXPECT_EQ(meta["errorStorage"], ToString(c.storage));
    EXPECT_EQ(meta["errorMax"], FormatDouble(SummarizeStoredBounds(t, c.storage).max));
    // Every texel, as the storage holds the value.
    EXPECT_EQ(k["levelByteLength"], t.values.size() * typeSize);
    EXPECT_EQ(k["uncompressedByteLength"], t.values.size() * typeSize);
    ASSERT_EQ(k["values"].size(), t.values.size());
    for (size_t i = 0; i < t.values.size(); ++i)
      ASSERT_EQ(k["values"][i].get<double>(), StoredValue(t.values[i], c.storage)) << i;
    // lutbake's reader, for check.
    const Table back = ReadKtx2Table(path);
    EXPECT_EQ(back.is3D(), t.is3D());
    EXPECT_EQ(DescribeAxis(back.z), DescribeAxis(t.z));
    ASSERT_EQ(back.values.size(), t.values.size());
    for (size_t i = 0; i < t.values.size(); ++i)
      ASSERT_EQ(back.values[i], StoredValue(t.values[i], c.storage)) << i;
  }
}

TEST(Ktx2Table, SecondWriteGivesTheSameBytes) {
  const fs::path dir = FormatTempDir("ktx2_again");
  const Table t = test::ThreeSliceTable();
  MakeKtx2Writer(ValueType::kHalf)->Write(t, (dir / "a.ktx2").string(), {});
  MakeKtx2Writer(ValueType::kHalf)->Write(t, (dir / "b.ktx2").string(), {});
  EXPECT_EQ(test::FileBytes(dir / "a.ktx2"), test::FileBytes(dir / "b.ktx2"));
}

TEST(Ktx2Table, ReaderRejectsATruncatedFile) {
  const fs::path dir = FormatTempDir("ktx2_cut");
  const std::string path = (dir / "E.ktx2").string();
  MakeKtx2Writer(ValueType::kFloat32)->Write(test::SmallTableOf(TableNamed("E")), path, {});
  fs::resize_file(path, fs::file_size(path) - 4);
  EXPECT_THROW(ReadKtx2Table(path), IoError);
}

}  // namespace
}  // namespace lutbake
