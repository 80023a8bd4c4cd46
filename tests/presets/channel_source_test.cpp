// The one list of what a preset channel may hold (src/presets/
// channel_source.cpp): each meaning reads the registered table and channel
// it names, at the point the texel gives that table, bit for bit what the
// table's own Evaluate gives there; an LTC entry is the fit of the table
// the channel names, and its divisor (HDRP's m22 = 1) divides the same
// fit; what the list cannot read is refused with the texture's name.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lutbake/presets/preset.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {
namespace {

PresetAxis Axis(const char *quantity, int count) {
  PresetAxis a;
  a.quantity = quantity;
  a.count = count;
  return a;
}

// A texture over (mu, roughness), texel centres, with `channels`.
PresetTexture Texture(std::vector<PresetChannel> channels, int count = 4) {
  PresetTexture t;
  t.file = "test.exr";
  t.format = "exr";
  t.axes = {Axis("mu", count), Axis("roughness", count)};
  t.channels = std::move(channels);
  return t;
}

TEST(PresetChannelSource, NamesTheRegisteredTableAndChannel) {
  const PresetChannelSource a = SourceOf({"A"});
  ASSERT_NE(a.table, nullptr);
  EXPECT_STREQ(a.table->Name(), "dfg");
  EXPECT_EQ(a.channel, "A");
  EXPECT_FALSE(a.fitted);
  EXPECT_EQ(SourceOf({"f82"}).channel, "C");
  EXPECT_STREQ(SourceOf({"disney_diffuse"}).table->Name(), "burley_E");
  // An LTC entry: the fit of the channel's table, ltc_ggx by default.
  const PresetChannelSource m00 = SourceOf({"ltc_m00"});
  EXPECT_STREQ(m00.table->Name(), "ltc_ggx");
  EXPECT_TRUE(m00.fitted);
  EXPECT_EQ(m00.lobe, "ggx");
  const PresetChannelSource burley = SourceOf({"ltc_m22", "ltc_burley"});
  EXPECT_STREQ(burley.table->Name(), "ltc_burley");
  EXPECT_EQ(burley.channel, "m22");
  EXPECT_EQ(burley.lobe, "burley (perceptual roughness sqrt(alpha))");
  EXPECT_EQ(SourceOf({"ltc_m11", "ltc_sheen"}).channel, "");
  // Quantities no table holds.
  for (const char *derived : {"sheen_B", "fabric_lambert", "zeltner_R", "clipped_sphere", "one"})
    EXPECT_EQ(SourceOf({derived}).table, nullptr) << derived;
}

TEST(PresetChannelSource, RefusesWhatTheListCannotRead) {
  EXPECT_THROW(SourceOf({"albedo"}), std::invalid_argument);
  EXPECT_THROW(SourceOf({"A", "ltc_ggx"}), std::invalid_argument);    // A is dfg's only
  EXPECT_THROW(SourceOf({"ltc_m00", "dfg"}), std::invalid_argument);  // dfg fits no lobe
  EXPECT_THROW(SourceOf({"one", "dfg"}), std::invalid_argument);      // reads no table
  EXPECT_THROW(SourceOf({"ltc_m00", "no_such"}), std::invalid_argument);
  const int index[3] = {0, 0, 0};
  double values[4], errors[4];
  // Two fits in one texture; a divisor of a channel that is not a fit.
  PresetTexture two = Texture({{"ltc_m00"}, {"ltc_m22", "ltc_burley"}});
  EXPECT_THROW(BakePresetTexture(two, "test"), std::invalid_argument);
  PresetTexture over = Texture({{"A", "", "ltc_m22"}});
  EXPECT_THROW(PresetTexelValues(over, index, values, errors), std::invalid_argument);
  // A fitted G2 integrates the split sum only: a GGX fit would ignore it.
  PresetTexture fitted = Texture({{"ltc_m00"}});
  fitted.model.fitted = FittedVisibility::kSchlickGgx;
  try {
    BakePresetTexture(fitted, "test");
    ADD_FAILURE() << "a GGX fit under a fitted G2 was baked";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("test.exr"), std::string::npos) << e.what();
  }
  // A channel that reads eta needs an eta axis; a texture without mu, a
  // channel that reads mu.
  EXPECT_THROW(PresetTexelValues(Texture({{"glass_E"}}), index, values, errors),
               std::invalid_argument);
  PresetTexture noMu = Texture({{"A"}});
  noMu.axes = {Axis("roughness", 4)};
  EXPECT_THROW(PresetTexelValues(noMu, index, values, errors), std::invalid_argument);
}

// The split-sum channels and Burley's albedo are the tables' own values at
// (mu, sqrt(alpha)) and (mu, roughness), E is A + B, and each bound the
// table's.
TEST(PresetChannelSource, ChannelsAreTheTablesValues) {
  PresetTexture t = Texture({{"A"}, {"B"}, {"E"}, {"disney_diffuse"}, {"one"}, {"zero"}});
  t.model.alphaMin = 0.05;  // alpha = max(r^2, 0.05): the clamp reaches two rows
  const TableDefinition &dfg = TableNamed("dfg"), &burley = TableNamed("burley_E");
  const BakeSettings settings = t.model.TableSettings();
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int index[3] = {i, j, 0};
      double v[6], e[6];
      PresetTexelValues(t, index, v, e);
      const double mu = t.axes[0].Quantity(i), q = t.axes[1].Quantity(j);
      const double alpha = std::max(q * q, 0.05);
      const PointValue ab = dfg.Evaluate(settings, mu, std::sqrt(alpha));
      EXPECT_EQ(v[0], ab.value[0]);
      EXPECT_EQ(v[1], ab.value[1]);
      EXPECT_EQ(v[2], ab.value[0] + ab.value[1]);
      EXPECT_EQ(e[0], ab.error[0]);
      EXPECT_EQ(e[2], ab.error[0] + ab.error[1]);
      EXPECT_GT(e[0], 0.0);
      const PointValue b = burley.Evaluate(settings, mu, q);  // the roughness axis itself
      EXPECT_EQ(v[3], b.value[0] / 1.03571);
      EXPECT_EQ(e[3], b.error[0] / 1.03571);
      EXPECT_EQ(v[4], 1.0);
      EXPECT_EQ(v[5], 0.0);
    }
}

// HDRP's divisor: each entry of the fit over its m22, the fit the same
// with and without it; the entries are those of the channel's table's fit
// (ltc_burley's differ from ltc_ggx's), and m11 = 1 before the division.
TEST(PresetChannelSource, LtcEntriesAreTheNamedTablesFitOverItsDivisor) {
  const std::vector<const char *> entries = {"ltc_m00", "ltc_m20", "ltc_m02", "ltc_m22", "ltc_m11"};
  const auto texture = [&](const char *table, const char *over) {
    std::vector<PresetChannel> channels;
    for (const char *entry : entries) channels.push_back({entry, table, over});
    PresetTexture t = Texture(channels, 3);
    t.model.alphaMin = 0.002;
    return t;
  };
  const Table plain = BakePresetTexture(texture("ltc_burley", ""), "test");
  const Table scaled = BakePresetTexture(texture("ltc_burley", "ltc_m22"), "test");
  const Table ggx = BakePresetTexture(texture("", ""), "test");
  double differs = 0.0;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      const double m22 = plain.value(x, y, 3);
      ASSERT_GT(m22, 0.0);
      EXPECT_EQ(plain.value(x, y, 4), 1.0);
      for (int c = 0; c < 5; ++c) {
        EXPECT_EQ(scaled.value(x, y, c), plain.value(x, y, c) / m22) << x << " " << y << " " << c;
        EXPECT_EQ(scaled.errors[scaled.index(x, y, c)], 0.0);
        differs = std::max(differs, std::abs(plain.value(x, y, c) - ggx.value(x, y, c)));
      }
    }
  EXPECT_GT(differs, 1e-3) << "ltc_burley's fit must not be ltc_ggx's";
}

}  // namespace
}  // namespace lutbake
