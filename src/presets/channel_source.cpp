// What a preset channel holds, in one place: the registered tables the
// presets read and the point a texel gives each (the engine's model turned
// into the table's coordinates), the meanings a channel may name (a table's
// channel, or a quantity no table holds), and a texture's channels resolved
// against them once.
#include "channel_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lutbake/core/math.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/models/zeltner_sheen_ltc.h"
#include "lutbake/tables/fitted_lobe.h"

namespace lutbake {

// The axes a quantity reads.
constexpr unsigned kMu = 1, kRoughness = 2, kEta = 4;

// How the presets read a registered table: the table's point (x, y, z) at a
// texel, and what of the model replaces the table where the engine says so.
struct PresetTableReading {
  const char *name;
  unsigned reads;
  std::array<double, 3> (*point)(const PresetTexel &);
  // The lobe of a table that fits one, with its parameter from the model's
  // alpha (preset.json's ltcLobe).
  const char *lobe = "";
  // Within the model's unitEtaWindow of eta = 1 the engine has no interface:
  // the value is 1 (glass).
  bool indexMatched = false;
  // Under the model's fitted G2 the same panel quadrature integrates the
  // split sum with that G2 (albedo_quadrature.h), not the table's Smith.
  bool fittedVisibility = false;
  const TableDefinition *table = nullptr;  // looked up once
};

// A meaning a channel may name: a table's channel (with a second added and
// a divisor), an entry of a table's LTC fit, or a quantity no table holds.
struct PresetQuantity {
  const char *name;
  const char *table = nullptr;    // the table read (a fit's: the default)
  const char *channel = nullptr;  // its channel's meaning there (a fit's m11: none)
  const char *plus = nullptr;     // a second channel added (E = A + B)
  double divisor = 1.0;           // value and bound over this
  bool fitted = false;            // an entry of the table's LTC fit
  PointValue (*derived)(const PresetTexel &) = nullptr;  // no table
  unsigned reads = 0;                                    // of a derived one
};

double PresetAlpha(const PresetModel &model, double q) {
  return std::max(AlphaFromRoughness(model.alpha, q), model.alphaMin);
}

namespace {

// The bound asked of the sheen's Schlick-weighted part (HDRP's Charlie x):
// the adaptive reference costs ~30 ms a point at 1e-8; at 1e-7 the stated
// bound (which the file's errorMax carries) is still 1e4 below the 10-bit
// storage HDRP renders the texture into.
constexpr double kSheenBTolerance = 1e-7;

// Unity HDRP's DisneyDiffuseNoPI divides F(mu_i) F(mu_o) by 1.03571 (29/28
// rounded, the albedo at mu_o = 1 and perceptual roughness 1), so its
// albedo is table burley_E's over 1.03571.
constexpr double kHdrpDisneyNormalisation = 1.03571;

// The perceptual roughness r = sqrt(alpha) of the microfacet tables' y.
double PerceptualRoughness(const PresetTexel &t) { return std::sqrt(t.alpha); }

// The sheen's roughness with the engine's clamp of its alpha.
double SheenRoughness(const PresetTexel &t) {
  const PresetModel &m = *t.model;
  return m.sheenAlpha == AlphaMapping::kSquared ? std::max(t.roughness, std::sqrt(m.sheenAlphaMin))
                                                : std::max(t.roughness, m.sheenAlphaMin);
}

// ltc_code's horizon-clipped sphere: a spherical cap whose vector form
// factor has length len = sin^2(sigma) (sigma its half-angle) and direction
// at cos(omega) = z from the normal, clipped at the horizon:
//   F = (1 / pi) int_cap max(w.z, 0) dw,   returned as F / len
// (max(z, 0) at len = 0). With t the angle from the cap's axis and phi
// around it, w.z = a - b cos(phi), a = cos(omega) cos(t), b = sin(omega)
// sin(t) >= 0, and the integral over phi is closed:
//   2 pi a (a >= b),  0 (a <= -b),  else 2 a (pi - phi0) + 2 b sin(phi0), cos(phi0) = a / b.
// Over t in [0, sigma] it changes form at t = |pi / 2 - omega|, where it
// behaves as (t - t*)^(3/2): Gauss-Legendre on each side of that point
// under the smoothstep map t = p + (q - p)(3 s^2 - 2 s^3), whose flat ends
// make the integrand smooth in s. Agrees with ltc_code's table to its 6
// digits.
double ClippedSphere(double z, double len) {
  z = std::clamp(z, -1.0, 1.0);
  if (!(len > 0.0)) return std::max(z, 0.0);
  const double sigma = std::asin(std::sqrt(std::min(len, 1.0)));
  const double omega = std::acos(z), co = std::cos(omega), so = std::sin(omega);
  const auto inner = [&](double t) {
    const double a = co * std::cos(t), b = so * std::sin(t);
    if (a >= b) return 2.0 * kPi * a;
    if (a <= -b) return 0.0;
    const double phi0 = std::acos(a / b);
    return 2.0 * a * (kPi - phi0) + 2.0 * b * std::sin(phi0);
  };
  std::vector<double> breaks = {0.0};
  const double kink = std::fabs(kPi / 2 - omega);
  if (kink > 0.0 && kink < sigma) breaks.push_back(kink);
  breaks.push_back(sigma);
  const GaussLegendreRule &rule = GaussLegendre(32);
  constexpr int kPanels = 4;
  double sum = 0.0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double p = breaks[k], q = breaks[k + 1];
    for (int panel = 0; panel < kPanels; ++panel)
      for (int n = 0; n < rule.n; ++n) {
        const double s = (panel + rule.x[n]) / kPanels;
        const double t = p + (q - p) * s * s * (3.0 - 2.0 * s);
        const double dt = (q - p) * 6.0 * s * (1.0 - s);
        sum += rule.w[n] / kPanels * dt * inner(t) * std::sin(t);
      }
  }
  return sum / kPi / len;
}

PointValue Constant(double value) {
  PointValue v;
  v.value[0] = value;
  return v;
}

// The split-sum terms {A, B} at (mu, alpha) under a fitted G2, by the panel
// quadrature of table dfg (albedo_quadrature.h); at alpha = 0 (the mirror:
// G2 = 1 in every form, o.h = mu) A = 1 - (1 - mu)^5 and B = (1 - mu)^5
// exactly.
PointValue FittedSplitSum(const PresetModel &model, double mu, double alpha) {
  PointValue v;
  v.quadrature = true;
  if (alpha == 0.0) {
    const double fc = std::pow(1.0 - mu, 5.0);
    v.value[0] = 1.0 - fc;
    v.value[1] = fc;
    v.exact = true;
    return v;
  }
  const SplitSumQuadrature q =
      IntegrateFittedSplitSumQuadrature(alpha, model.fitted, mu, kDefaultQuadratureTolerance);
  if (!q.converged)
    throw std::runtime_error("the fitted split sum did not converge at mu = " + FormatDouble(mu) +
                             ", alpha = " + FormatDouble(alpha));
  v.value[0] = q.A;
  v.value[1] = q.B;
  v.error[0] = q.boundA;
  v.error[1] = q.boundB;
  return v;
}

// The points of the tables: (mu, r), (r), (mu, r, eta), (r, eta).
using Point = std::array<double, 3>;
Point MuR(const PresetTexel &t) { return {t.mu, PerceptualRoughness(t), 0.0}; }
Point R(const PresetTexel &t) { return {PerceptualRoughness(t), 0.0, 0.0}; }
Point MuREta(const PresetTexel &t) { return {t.mu, PerceptualRoughness(t), t.eta}; }
Point REta(const PresetTexel &t) { return {PerceptualRoughness(t), t.eta, 0.0}; }

// Every table a preset reads, and the point a texel gives it.
const std::vector<PresetTableReading> &Readings() {
  static const std::vector<PresetTableReading> readings = [] {
    constexpr unsigned kLobe = kMu | kRoughness;
    std::vector<PresetTableReading> r = {
        // name, reads, point, lobe, indexMatched, fittedVisibility
        {"dfg", kLobe, MuR, "", false, true},
        {"f82", kLobe, MuR},
        {"Eavg", kRoughness, R},
        {"sheen_E", kLobe,
         [](const PresetTexel &t) {
           return Point{t.mu, SheenRoughness(t), 0};
         }},
        {"glass_E", kLobe | kEta, MuREta, "", true},
        {"glass_Eavg", kRoughness | kEta, REta, "", true},
        {"spec_E", kLobe | kEta, MuREta},
        {"spec_Eavg", kRoughness | kEta, REta},
        // Burley's diffuse at the engine's perceptual roughness itself.
        {"burley_E", kLobe,
         [](const PresetTexel &t) {
           return Point{t.mu, t.roughness, 0.0};
         }},
        // The LTC tables: the lobe at the table's y from the model's alpha.
        {"ltc_ggx", kLobe, MuR, "ggx"},
        {"ltc_burley", kLobe, MuR, "burley (perceptual roughness sqrt(alpha))"},
        // y: the sheen roughness whose sheen alpha is alpha.
        {"ltc_sheen", kLobe,
         [](const PresetTexel &t) {
           const bool squared = t.model->sheenAlpha == AlphaMapping::kSquared;
           return Point{t.mu, squared ? std::sqrt(t.alpha) : t.alpha, 0.0};
         },
         "sheen (alpha)"},
        // sigma = (pi / 2) alpha radians (Unity HDRP's BRDF_OrenNayar mapping).
        {"ltc_oren_nayar", kLobe,
         [](const PresetTexel &t) {
           return Point{t.mu, 0.5 * kPi * t.alpha, 0.0};
         },
         "oren-nayar qualitative (sigma = pi/2 alpha)"},
    };
    for (PresetTableReading &reading : r) reading.table = &TableNamed(reading.name);
    return r;
  }();
  return readings;
}

const PresetTableReading *ReadingOf(const std::string &table) {
  for (const PresetTableReading &r : Readings())
    if (table == r.name) return &r;
  return nullptr;
}

// Every meaning a channel may name (preset.h lists them in words).
const std::vector<PresetQuantity> &Quantities() {
  static const std::vector<PresetQuantity> quantities = [] {
    std::vector<PresetQuantity> q;
    const auto table = [&](const char *name, const char *t, const char *channel,
                           const char *plus = nullptr, double divisor = 1.0) {
      q.push_back({name, t, channel, plus, divisor});
    };
    const auto fit = [&](const char *name, const char *entry) {
      q.push_back({name, "ltc_ggx", entry, nullptr, 1.0, true});
    };
    const auto derived = [&](const char *name, unsigned reads,
                             PointValue (*value)(const PresetTexel &)) {
      q.push_back({name, nullptr, nullptr, nullptr, 1.0, false, value, reads});
    };
    table("A", "dfg", "A");
    table("B", "dfg", "B");
    table("E", "dfg", "A", "B");
    table("Eavg", "Eavg", "Eavg");
    table("sheen_E", "sheen_E", "sheen_E");
    table("f82", "f82", "C");
    table("glass_E", "glass_E", "glass_E");
    table("glass_Eavg", "glass_Eavg", "glass_Eavg");
    table("spec_E", "spec_E", "spec_E");
    table("spec_Eavg", "spec_Eavg", "spec_Eavg");
    table("disney_diffuse", "burley_E", "burley_E", nullptr, kHdrpDisneyNormalisation);
    fit("ltc_m00", "m00");
    fit("ltc_m20", "m20");
    fit("ltc_m02", "m02");
    fit("ltc_m22", "m22");
    fit("ltc_m11", nullptr);
    derived("sheen_B", kMu | kRoughness, [](const PresetTexel &t) {
      const PresetModel &m = *t.model;
      const SheenIntegral b = IntegrateSheenSchlickWeightedAdaptive(
          m.sheenVisibility, AlphaFromRoughness(m.sheenAlpha, t.roughness), t.mu, kSheenBTolerance);
      PointValue v = Constant(b.value);
      v.error[0] = b.bound;
      return v;
    });
    // HDRP's FabricLambertNoPI: lerp(1, 1/2, alpha), alpha = roughness^2.
    derived("fabric_lambert", kRoughness,
            [](const PresetTexel &t) { return Constant(1.0 - 0.5 * t.alpha); });
    // The published table, at alpha = the roughness axis.
    derived("zeltner_a", kMu | kRoughness,
            [](const PresetTexel &t) { return Constant(ZeltnerSheenLtc(t.mu, t.roughness)[0]); });
    derived("zeltner_b", kMu | kRoughness,
            [](const PresetTexel &t) { return Constant(ZeltnerSheenLtc(t.mu, t.roughness)[1]); });
    derived("zeltner_R", kMu | kRoughness,
            [](const PresetTexel &t) { return Constant(ZeltnerSheenLtc(t.mu, t.roughness)[2]); });
    // Geometry alone: the texture coordinates, no lobe (any axes do).
    derived("clipped_sphere", 0,
            [](const PresetTexel &t) { return Constant(ClippedSphere(2.0 * t.u - 1.0, t.v)); });
    derived("one", 0, [](const PresetTexel &) { return Constant(1.0); });
    derived("zero", 0, [](const PresetTexel &) { return Constant(0.0); });
    return q;
  }();
  return quantities;
}

const PresetQuantity &QuantityNamed(const std::string &meaning) {
  for (const PresetQuantity &q : Quantities())
    if (meaning == q.name) return q;
  throw std::invalid_argument("preset channel '" + meaning + "' is not known");
}

// The reading of the table `quantity` reads, `table` naming another fit.
const PresetTableReading *TableOf(const PresetQuantity &quantity, const std::string &table) {
  if (!quantity.table) {
    if (!table.empty())
      throw std::invalid_argument("preset channel '" + std::string(quantity.name) +
                                  "' reads no table; it takes no table '" + table + "'");
    return nullptr;
  }
  const std::string name = table.empty() ? quantity.table : table;
  const PresetTableReading *reading = ReadingOf(name);
  const bool allowed = name == quantity.table || (quantity.fitted && FitsLobe(TableNamed(name)));
  if (!reading || !allowed)
    throw std::invalid_argument("preset channel '" + std::string(quantity.name) +
                                "' cannot read table '" + name + "'");
  return reading;
}

// The index of the channel whose meaning is `meaning` in `table`.
int ChannelIndex(const TableDefinition &table, const char *meaning) {
  if (!meaning) return -1;
  const std::vector<std::string> meanings = table.ChannelMeanings();
  for (size_t c = 0; c < meanings.size(); ++c)
    if (meanings[c] == meaning) return static_cast<int>(c);
  throw std::logic_error(std::string("table ") + table.Name() + " has no channel " + meaning);
}

}  // namespace

PresetChannelSource SourceOf(const PresetChannel &channel) {
  const PresetQuantity &q = QuantityNamed(channel.meaning);
  PresetChannelSource source;
  if (const PresetTableReading *reading = TableOf(q, channel.table)) {
    source.table = reading->table;
    source.channel = q.channel ? q.channel : "";
    source.lobe = reading->lobe;
  }
  source.fitted = q.fitted;
  return source;
}

PresetChannelPlan::Channel PresetChannelPlan::Resolve(const std::string &meaning,
                                                      const std::string &table, unsigned *reads) {
  Channel c;
  c.quantity = &QuantityNamed(meaning);
  const PresetTableReading *reading = TableOf(*c.quantity, table);
  *reads |= reading ? reading->reads : c.quantity->reads;
  if (!reading) return c;
  c.channel = ChannelIndex(*reading->table, c.quantity->channel);
  c.plus = ChannelIndex(*reading->table, c.quantity->plus);
  if (c.quantity->fitted) {  // no table value: an entry of the fit
    if (fittedTable_ && fittedTable_ != reading)
      throw std::invalid_argument(texture_->file + ": its LTC channels are fits of two tables, " +
                                  fittedTable_->name + " and " + reading->name);
    fittedTable_ = reading;
    return c;
  }
  // Each table read once a texel.
  auto at = std::find(readings_.begin(), readings_.end(), reading);
  if (at == readings_.end()) at = readings_.insert(at, reading);
  c.reading = static_cast<int>(at - readings_.begin());
  return c;
}

PresetChannelPlan::PresetChannelPlan(const PresetTexture &texture) : texture_(&texture) {
  const std::string &file = texture.file;
  unsigned reads = 0;
  for (const PresetChannel &channel : texture.channels) {
    Channel c = Resolve(channel.meaning, channel.table, &reads);
    if (!channel.over.empty()) {
      const Channel over = Resolve(channel.over, channel.table, &reads);
      if (!c.quantity->fitted || !over.quantity->fitted)
        throw std::invalid_argument(file + ": channel '" + channel.meaning + "' over '" +
                                    channel.over + "': only the LTC fit's entries are divided");
      c.over = static_cast<int>(divisors_.size());
      divisors_.push_back(over);
    }
    channels_.push_back(c);
  }
  // A fitted G2 replaces Smith's in the split sum only: a fit of a table
  // whose model takes a Smith form would silently use the exact one.
  if (fittedTable_ && texture.model.fitted != FittedVisibility::kNone) {
    const std::vector<std::string> options = fittedTable_->table->ModelOptions();
    if (std::find(options.begin(), options.end(), "smith") != options.end())
      throw std::invalid_argument(file + ": the LTC channels of table " + fittedTable_->name +
                                  " take an exact Smith form");
  }

  if (texture.axes.empty() || texture.axes.size() > 3)
    throw std::invalid_argument(file + ": a preset texture has one to three axes");
  for (size_t a = 0; a < texture.axes.size(); ++a) {
    const std::string &quantity = texture.axes[a].quantity;
    if (quantity == "mu") muAxis = static_cast<int>(a);
    if (quantity == "roughness") roughnessAxis = static_cast<int>(a);
    if (quantity == "eta" || quantity == "1/eta") etaAxis = static_cast<int>(a);
  }
  if (((reads & kRoughness) && roughnessAxis < 0) || ((reads & kMu) && muAxis < 0))
    throw std::invalid_argument(file + ": a preset texture needs its mu and roughness axes");
  if (((reads & kEta) != 0) != (etaAxis >= 0))
    throw std::invalid_argument(
        file + ": the dielectric (glass, spec) channels, and only they, take an eta axis");
}

LtcLobe PresetChannelPlan::LobeAt(double q) const {
  PresetTexel texel;
  texel.model = &texture_->model;
  texel.settings = texture_->model.TableSettings();
  texel.roughness = q;
  texel.alpha = PresetAlpha(texture_->model, q);
  return FittedLobe(*fittedTable_->table, texel.settings, fittedTable_->point(texel)[1]);
}

PresetTexture PresetChannelPlan::WithoutFit() const {
  PresetTexture others = *texture_;
  others.channels.clear();
  for (size_t c = 0; c < channels_.size(); ++c)
    if (!channels_[c].quantity->fitted) others.channels.push_back(texture_->channels[c]);
  return others;
}

double PresetChannelPlan::ValueOf(const Channel &c, const PresetTexel &texel,
                                  const std::vector<PointValue> &read, const LtcMatrix *fit,
                                  double *error) const {
  const PresetQuantity &q = *c.quantity;
  *error = 0.0;
  if (q.fitted) {
    // The fit is the value (its bound 0; what it is worth is the lobe
    // error that eval --table ltc_* states), in the table's channel order.
    const double entries[] = {fit->m00, fit->m20, fit->m02, fit->m22};
    return c.channel < 0 ? 1.0 : entries[c.channel];
  }
  if (q.derived) {
    const PointValue v = q.derived(texel);
    *error = v.error[0];
    return v.value[0];
  }
  const PointValue &v = read[static_cast<size_t>(c.reading)];
  double value = v.value[c.channel];
  *error = v.error[c.channel];
  if (c.plus >= 0) {
    value += v.value[c.plus];
    *error += v.error[c.plus];
  }
  if (q.divisor != 1.0) {
    value /= q.divisor;
    *error /= q.divisor;
  }
  return value;
}

void PresetChannelPlan::Channels(const PresetTexel &texel, const LtcMatrix *fit, double *values,
                                 double *errors) const {
  const PresetModel &model = *texel.model;
  // Each table read once.
  std::vector<PointValue> read(readings_.size());
  for (size_t k = 0; k < readings_.size(); ++k) {
    const PresetTableReading &r = *readings_[k];
    const std::array<double, 3> p = r.point(texel);
    if (r.indexMatched && std::abs(texel.eta - 1.0) < model.unitEtaWindow)
      read[k].value[0] = 1.0;  // the engine's own index-matched interface: no lobe
    else if (r.fittedVisibility && model.fitted != FittedVisibility::kNone)
      read[k] = FittedSplitSum(model, texel.mu, texel.alpha);
    else
      read[k] = r.table->Evaluate3D(texel.settings, p[0], p[1], p[2]);
  }
  for (size_t c = 0; c < channels_.size(); ++c) {
    const PresetChannel &channel = texture_->channels[c];
    const Channel &resolved = channels_[c];
    double error = 0.0;
    double value = ValueOf(resolved, texel, read, fit, &error);
    if (resolved.over >= 0) {
      double unused = 0.0;
      const double divisor =
          ValueOf(divisors_[static_cast<size_t>(resolved.over)], texel, read, fit, &unused);
      if (!(divisor > 0.0))
        throw std::runtime_error(texture_->file + ": " + channel.over + " is " +
                                 FormatDouble(divisor) + " at mu = " + FormatDouble(texel.mu) +
                                 ", roughness = " + FormatDouble(texel.roughness) + ": " +
                                 channel.meaning + " cannot be divided by it");
      value /= divisor;  // correctly rounded
    }
    const double stored = channel.scale * value + channel.offset;
    values[c] = std::clamp(stored, channel.clampMin, channel.clampMax);
    // clampIsValue: the engine's own table is the clamped integral, so the
    // clamp moves nothing away from it (preset.h).
    errors[c] = std::fabs(channel.scale) * error +
                (channel.clampIsValue ? 0.0 : std::abs(stored - values[c]));
  }
}

}  // namespace lutbake
