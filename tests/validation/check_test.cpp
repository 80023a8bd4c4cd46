// CheckBakedSet (`lutbake check`): passes on a good bake, fails with a
// reason on every kind of tampering; the lookup it judges with, and the
// readers it uses. The command line's exit statuses and messages are
// tests/cli/bake_cli_test.cpp.
#include "lutbake/validation/check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/lutbake.h"
#include "lutbake/tables/lookup.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

// A small complete set (sampled E, dfg, Eavg; Schlick Favg) baked once
// (bake --size 8 --samples 4096 --error-map).
const fs::path &GoodBake() {
  static const fs::path dir = [] {
    const fs::path d = test::Scratch("check_good");
    BakeRequest request = test::BakeRequestFor(d);
    request.size = 8;
    request.sampling.samples = 4096;
    request.errorMaps = true;
    Bake(request);
    return d;
  }();
  return dir;
}

fs::path CopyOfGood(const std::string &name) {
  const fs::path d = test::Scratch(name);
  fs::copy(GoodBake(), d, fs::copy_options::recursive);
  return d;
}

CheckOptions Quick() {
  CheckOptions o;
  o.randomPoints = 32;
  o.furnaceGrid = 65;
  return o;
}

const CheckResult *Find(const CheckReport &r, const std::string &subject,
                        const std::string &check) {
  for (const CheckResult &c : r.results)
    if (c.subject == subject && c.check == check) return &c;
  return nullptr;
}

// Rewrites value `index` of a .bin file (float32 at the data offset).
void PatchBin(const fs::path &path, size_t index, float value) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  char offset[4];
  f.seekg(12);
  f.read(offset, 4);
  uint32_t dataOffset;
  std::memcpy(&dataOffset, offset, 4);
  f.seekp(dataOffset + 4 * static_cast<std::streamoff>(index));
  f.write(reinterpret_cast<const char *>(&value), 4);
}

float BinValue(const fs::path &path, size_t index) {
  return static_cast<float>(ReadBinaryTable(path.string()).values[index]);
}

TEST(Check, PassesOnAGoodBake) {
  const CheckReport r = CheckBakedSet(GoodBake().string(), Quick());
  for (const CheckResult &c : r.results)
    EXPECT_NE(c.status, CheckStatus::kFail) << c.subject << " " << c.check << ": " << c.detail;
  EXPECT_TRUE(r.passed());
  // Every check ran on the full set.
  for (const auto &[subject, check] :
       std::vector<std::pair<std::string, std::string>>{{"E", "metadata"},
                                                        {"E", "formats"},
                                                        {"E", "finite"},
                                                        {"E", "range"},
                                                        {"E", "texels"},
                                                        {"E", "points"},
                                                        {"dfg", "texels"},
                                                        {"Eavg", "monotonic"},
                                                        {"Favg", "closed form"},
                                                        {"Favg", "monotonic"},
                                                        {"E+dfg", "identity"},
                                                        {"E+Eavg", "average"},
                                                        {"E+Eavg", "furnace"}}) {
    const CheckResult *c = Find(r, subject, check);
    ASSERT_NE(c, nullptr) << subject << " " << check;
    EXPECT_EQ(c->status, CheckStatus::kPass) << subject << " " << check << ": " << c->detail;
  }
  // The furnace reports where it is worst.
  EXPECT_EQ(Find(r, "E+Eavg", "furnace")->at.size(), 2u);
}

TEST(Check, FailsOnATamperedTexel) {
  const fs::path d = CopyOfGood("check_texel");
  fs::remove(d / "E.exr");
  fs::remove(d / "E.h");
  // 20x the stated errorMax at one interior texel of E.bin.
  const Table before = ReadBinaryTable((d / "E.bin").string());
  const size_t i = before.index(3, 4, 0);
  PatchBin(d / "E.bin", i, static_cast<float>(before.values[i] - 20.0 * before.MaxError()));
  const CheckReport r = CheckBakedSet(d.string(), Quick());
  EXPECT_FALSE(r.passed());
  const CheckResult *texels = Find(r, "E", "texels");
  ASSERT_NE(texels, nullptr);
  EXPECT_EQ(texels->status, CheckStatus::kFail) << texels->detail;
  EXPECT_NEAR(texels->at[0].second, before.x.TexelCenter(3), 1e-12);
  EXPECT_NEAR(texels->at[1].second, before.y.TexelCenter(4), 1e-12);
  fs::remove_all(d);
}

TEST(Check, FailsWhenFormatsDisagree) {
  const fs::path d = CopyOfGood("check_formats");
  PatchBin(d / "dfg.bin", 5, BinValue(d / "dfg.bin", 5) + 1e-3f);
  const CheckReport r = CheckBakedSet(d.string(), Quick());
  const CheckResult *formats = Find(r, "dfg", "formats");
  ASSERT_NE(formats, nullptr);
  EXPECT_EQ(formats->status, CheckStatus::kFail);
  EXPECT_NE(formats->detail.find("dfg.bin differs"), std::string::npos) << formats->detail;
  fs::remove_all(d);
}

TEST(Check, FailsOnNanAndOutOfRange) {
  const fs::path d = CopyOfGood("check_nan");
  for (const char *f : {"dfg.exr", "dfg.h", "E.exr", "E.h"}) fs::remove(d / f);
  PatchBin(d / "dfg.bin", 7, std::nanf(""));
  PatchBin(d / "E.bin", 2, 1.01f);
  const CheckReport r = CheckBakedSet(d.string(), Quick());
  EXPECT_EQ(Find(r, "dfg", "finite")->status, CheckStatus::kFail);
  EXPECT_EQ(Find(r, "E", "range")->status, CheckStatus::kFail);
  EXPECT_NE(Find(r, "E", "range")->detail.find("E > 1"), std::string::npos);
  fs::remove_all(d);
}

TEST(Check, FailsOnAMixedSetAndOnForeignMetadata) {
  // E_avg from Beckmann next to GGX E: the furnace and the average refuse.
  const fs::path d = CopyOfGood("check_mixed");
  const fs::path other = test::Scratch("check_mixed_other");
  BakeRequest beckmann = test::BakeRequestFor(other);  // --tables Eavg --ndf beckmann
  beckmann.tables = {"Eavg"};
  beckmann.size = 8;
  beckmann.sampling.samples = 4096;
  beckmann.ndf = NdfKind::kBeckmann;
  Bake(beckmann);
  for (const char *f : {"Eavg.exr", "Eavg.bin", "Eavg.h"})
    fs::copy_file(other / f, d / f, fs::copy_options::overwrite_existing);
  fs::remove(d / "Eavg.err.exr");
  CheckReport r = CheckBakedSet(d.string(), Quick());
  EXPECT_EQ(Find(r, "E+Eavg", "furnace")->status, CheckStatus::kFail);
  EXPECT_NE(Find(r, "E+Eavg", "furnace")->detail.find("mixes models"), std::string::npos);
  // A header whose texel convention is not lutbake's cannot be trusted.
  const fs::path h = test::Scratch("check_header");
  fs::create_directories(h);
  std::ifstream in(GoodBake() / "E.h");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text = std::regex_replace(text, std::regex("texel i of N holds the value at u = \\(i \\+ 0.5\\)"),
                            "texel i of N holds the value at u = i / (N - 1)");
  std::ofstream(h / "E.h") << text;
  r = CheckBakedSet(h.string(), Quick());
  EXPECT_EQ(Find(r, "E", "metadata")->status, CheckStatus::kFail);
  EXPECT_NE(Find(r, "E", "metadata")->detail.find("texelConvention"), std::string::npos);
  fs::remove_all(d);
  fs::remove_all(other);
  fs::remove_all(h);
}

TEST(Check, HeaderAloneIsChecked) {
  // An engine's copy of the headers only (luts/-style): still checked.
  const fs::path h = test::Scratch("check_header_only");
  fs::create_directories(h);
  fs::copy_file(GoodBake() / "E.h", h / "E.h");
  fs::copy_file(GoodBake() / "Eavg.h", h / "Eavg.h");
  const CheckReport r = CheckBakedSet(h.string(), Quick());
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(Find(r, "E", "texels")->status, CheckStatus::kPass);
  EXPECT_EQ(Find(r, "E+Eavg", "furnace")->status, CheckStatus::kPass);
  fs::remove_all(h);
}

// Half-storage headers: beside the EXR each value must be the EXR's rounded
// to half (one half-ulp off is caught); alone, they pass with the storage
// rounding they state added to their bounds.
TEST(Check, HalfHeadersAreHeldToTheirRounding) {
  const fs::path d = test::Scratch("check_half");
  BakeRequest request = test::BakeRequestFor(d);  // --size 8 --tolerance 1e-6 --header-type half
  request.size = 8;
  request.sampling.tolerance = 1e-6;
  request.headerType = "half";
  Bake(request);
  CheckReport r = CheckBakedSet(d.string(), Quick());
  EXPECT_TRUE(r.passed());
  ASSERT_NE(Find(r, "dfg", "formats"), nullptr);
  EXPECT_EQ(Find(r, "dfg", "formats")->status, CheckStatus::kPass);
  // Headers alone: judged with their stated storage error.
  const fs::path h = test::Scratch("check_half_only");
  fs::create_directories(h);
  for (const char *name : {"E.h", "Eavg.h", "Favg.h", "dfg.h"}) fs::copy_file(d / name, h / name);
  r = CheckBakedSet(h.string(), Quick());
  EXPECT_TRUE(r.passed());
  // Move one half value by one unit in the last place: formats fails.
  std::ifstream in(d / "E.h");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const size_t at = text.find("0x", text.find("kValues["));
  ASSERT_NE(at, std::string::npos);
  const unsigned bits = static_cast<unsigned>(std::stoul(text.substr(at, 6), nullptr, 16));
  char patched[8];
  std::snprintf(patched, sizeof patched, "0x%04x", bits - 1);
  text.replace(at, 6, patched);
  std::ofstream(d / "E.h") << text;
  r = CheckBakedSet(d.string(), Quick());
  ASSERT_NE(Find(r, "E", "formats"), nullptr);
  EXPECT_EQ(Find(r, "E", "formats")->status, CheckStatus::kFail);
  fs::remove_all(d);
  fs::remove_all(h);
}

// The GPU texture files (PNG, KTX2, DDS): beside the EXR each holds its
// values as its storage rounds them ("texture formats"); one KTX2 texel
// moved by a float32 ulp fails; half or PNG files alone pass with their
// stored bounds.
TEST(Check, TextureFormatsAreHeldToTheirStorage) {
  const fs::path d = test::Scratch("check_textures");
  BakeRequest request = test::BakeRequestFor(d);
  request.size = 8;
  request.sampling.tolerance = 1e-6;
  request.formats = {"exr", "png16", "ktx2", "dds-half"};
  Bake(request);
  CheckReport r = CheckBakedSet(d.string(), Quick());
  EXPECT_TRUE(r.passed());
  const CheckResult *textures = Find(r, "dfg", "texture formats");
  ASSERT_NE(textures, nullptr);
  EXPECT_EQ(textures->status, CheckStatus::kPass);
  EXPECT_NE(textures->detail.find("dfg.ktx2 (float32), dfg.dds (half), dfg.png (unorm16)"),
            std::string::npos)
      << textures->detail;
  for (const char *format : {"ktx2-half", "png8"}) {
    const fs::path alone = test::Scratch(std::string("check_textures_") + format);
    BakeRequest single = test::BakeRequestFor(alone);
    single.size = 8;
    single.sampling.tolerance = 1e-6;
    single.formats = {format};
    Bake(single);
    r = CheckBakedSet(alone.string(), Quick());
    EXPECT_TRUE(r.passed()) << format;
    fs::remove_all(alone);
  }
  // The last float32 of dfg.ktx2's level (the level ends the file).
  const fs::path ktx2 = d / "dfg.ktx2";
  {
    std::fstream f(ktx2, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(-4, std::ios::end);
    float v;
    f.read(reinterpret_cast<char *>(&v), 4);
    v = std::nextafter(v, 2.0f);
    f.seekp(-4, std::ios::end);
    f.write(reinterpret_cast<const char *>(&v), 4);
  }
  r = CheckBakedSet(d.string(), Quick());
  textures = Find(r, "dfg", "texture formats");
  ASSERT_NE(textures, nullptr);
  EXPECT_EQ(textures->status, CheckStatus::kFail);
  EXPECT_NE(textures->detail.find("dfg.ktx2 differs at texel (7, 7) channel 1"), std::string::npos)
      << textures->detail;
  fs::remove_all(d);
}

TEST(Lookup, TexelCentresClampingAndTheMuIntegral) {
  Table t;
  t.x = LinearAxis("mu", 0.0, 1.0, 4);
  t.y = LinearAxis("perceptualRoughness", 0.0, 1.0, 3);
  t.channels = 1;
  // v = 2 + 3 mu + 5 r at the centres: bilinear reproduces it exactly
  // between the centres.
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      t.values.push_back(2.0 + 3.0 * t.x.TexelCenter(x) + 5.0 * t.y.TexelCenter(y));
  EXPECT_EQ(Lookup(t, t.x.TexelCenter(2), t.y.TexelCenter(1)), t.value(2, 1));
  EXPECT_NEAR(Lookup(t, 0.4, 0.5), 2.0 + 1.2 + 2.5, 1e-15);
  // Clamped outside the centres (mu < 1/8, r > 5/6).
  EXPECT_NEAR(Lookup(t, 0.0, 1.0), Lookup(t, 0.125, 5.0 / 6.0), 1e-15);
  // 2 integral_0^1 L mu dmu with L constant below 1/8 and above 7/8.
  const double r = 0.5, c = 2.0 + 5.0 * r;
  const auto f = [&](double mu) { return c + 3.0 * std::clamp(mu, 0.125, 0.875); };
  // Exact: the clamped pieces and the linear middle, integrated by hand.
  const double exact = f(0.0) * 0.125 * 0.125 +
                       (c * (0.875 * 0.875 - 0.125 * 0.125) +
                        2.0 * (0.875 * 0.875 * 0.875 - 0.125 * 0.125 * 0.125)) +
                       f(1.0) * (1.0 - 0.875 * 0.875);
  EXPECT_NEAR(LookupMuAverage(t, t.values, r, 0), exact, 1e-14);
}

TEST(Lookup, NanCoordinateReadsTheFirstTexel) {
  // Found by the .bin fuzzer (an axis [0, inf] gave NaN coordinates, and
  // casting NaN to int is undefined): a NaN value asked for reads texel 0.
  Table t;
  t.x = LinearAxis("mu", 0.0, 1.0, 4);
  t.y = LinearAxis("perceptualRoughness", 0.0, 1.0, 3);
  for (int i = 0; i < 12; ++i) t.values.push_back(i);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Lookup(t, nan, nan), t.value(0, 0));
  EXPECT_EQ(Lookup(t, nan, t.y.TexelCenter(2)), t.value(0, 2));
}

TEST(TableReader, ExrAndHeaderReadBackWhatWasWritten) {
  const Table exr = ReadExrTable((GoodBake() / "dfg.exr").string());
  const Table bin = ReadBinaryTable((GoodBake() / "dfg.bin").string());
  EXPECT_EQ(exr.definition, &TableNamed("dfg"));
  EXPECT_EQ(DescribeAxis(exr.x), DescribeAxis(bin.x));
  EXPECT_EQ(DescribeAxis(exr.y), DescribeAxis(bin.y));
  EXPECT_EQ(exr.values, bin.values);
  EXPECT_EQ(*exr.FindMetadata("ndf"), "ggx");
  const HeaderValues h = ReadHeaderValues((GoodBake() / "dfg.h").string());
  ASSERT_EQ(h.values.size(), bin.values.size());
  for (size_t i = 0; i < h.values.size(); ++i)
    EXPECT_EQ(h.values[i], static_cast<float>(bin.values[i]));
  Axis axis;
  EXPECT_TRUE(ParseAxisDescription("mu linear [0, 1], 32 texels", &axis));
  EXPECT_EQ(axis.count, 32);
  EXPECT_FALSE(ParseAxisDescription("mu linear [0, 1], 32", &axis));
  EXPECT_FALSE(ParseAxisDescription("mu linear [1, 0], 32 texels", &axis));
}

TEST(TableReader, MalformedBinaryIsRefused) {
  const fs::path d = test::Scratch("reader_bad");
  fs::create_directories(d);
  std::ifstream in(GoodBake() / "E.bin", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(d / "truncated.bin", std::ios::binary) << bytes.substr(0, bytes.size() - 5);
  EXPECT_THROW(ReadBinaryTable((d / "truncated.bin").string()), IoError);
  std::string huge = bytes;
  const uint32_t width = 1u << 30;
  std::memcpy(huge.data() + 20, &width, 4);
  std::ofstream(d / "huge.bin", std::ios::binary) << huge;
  EXPECT_THROW(ReadBinaryTable((d / "huge.bin").string()), IoError);
  std::ofstream(d / "text.bin") << "not a table";
  EXPECT_THROW(ReadBinaryTable((d / "text.bin").string()), IoError);
  EXPECT_THROW(ReadExrTable((d / "text.bin").string()), IoError);
  fs::remove_all(d);
}

}  // namespace
}  // namespace lutbake
