// Baking a preset's texture: the engine's coordinates of every texel, the
// model's alpha there, and the channels from lutbake's integrators.
#include "lutbake/presets/preset.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "lutbake/formats/writer.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/gauss_legendre.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/models/zeltner_sheen_ltc.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

const char *ToString(PresetMapping mapping) {
  switch (mapping) {
    case PresetMapping::kLinear: return "u";
    case PresetMapping::kSquare: return "u^2";
    case PresetMapping::kOneMinusSquare: return "1 - u^2";
    case PresetMapping::kIorOfF0Root4: return "(1 + u^2) / (1 - u^2)";
    case PresetMapping::kLinearRange: return "lowest + u (highest - lowest)";
  }
  return "?";
}

const char *ToString(TexelPlacement placement) {
  return placement == TexelPlacement::kCentres ? "centres" : "edges";
}

std::string DescribeVisibility(const PresetModel &model) {
  switch (model.fitted) {
    case FittedVisibility::kSchlickGgx: return "schlick-ggx k = alpha / 2";
    case FittedVisibility::kSmithJointApprox: return "smith-joint-approx a = alpha";
    case FittedVisibility::kNone: break;
  }
  return "smith-" + std::string(ToString(model.smith));
}

const char *DescribeAlpha(AlphaMapping alpha) {
  return alpha == AlphaMapping::kSquared ? "alpha = roughness^2" : "alpha = roughness";
}

BakeSettings PresetModel::TableSettings() const {
  BakeSettings settings;
  settings.smith = smith;
  settings.sheenVisibility = sheenVisibility;
  settings.sheenAlpha = sheenAlpha;
  return settings;
}

const char *ToString(PresetLtcLobe lobe) {
  switch (lobe) {
    case PresetLtcLobe::kGgx: return "ggx";
    case PresetLtcLobe::kBurley: return "burley (perceptual roughness sqrt(alpha))";
    case PresetLtcLobe::kSheen: return "sheen (alpha)";
    case PresetLtcLobe::kOrenNayar: return "oren-nayar qualitative (sigma = pi/2 alpha)";
  }
  return "?";
}

double PresetAxis::Coordinate(int i) const {
  if (placement == TexelPlacement::kEdges)
    return count > 1 ? static_cast<double>(i) / (count - 1) : 0.0;
  return (i + 0.5) / count;
}

double PresetAxis::Quantity(int i) const {
  // An index outside [0, N) (a table read one texel off) stands at the
  // axis's end: u is clamped to [0, 1] first.
  const double u = std::clamp(Coordinate(i), 0.0, 1.0);
  double q = u;
  if (mapping == PresetMapping::kSquare) q = u * u;
  if (mapping == PresetMapping::kOneMinusSquare) q = 1.0 - u * u;
  // (1 + u^2) / (1 - u^2), the IOR of F0 = u^4; 1 - u^2 = (1 - u)(1 + u)
  // without cancellation. u = 1 gives +infinity, which the clamp bounds.
  if (mapping == PresetMapping::kIorOfF0Root4)
    q = u < 1.0 ? (1.0 + u * u) / ((1.0 - u) * (1.0 + u)) : std::numeric_limits<double>::infinity();
  if (mapping == PresetMapping::kLinearRange) q = lowest + u * (highest - lowest);
  return std::clamp(q, lowest, highest);
}

namespace {

// The bound asked of the sheen's Schlick-weighted part (HDRP's Charlie x):
// the adaptive reference costs ~30 ms a point at 1e-8; at 1e-7 the stated
// bound (which the file's errorMax carries) is still 1e4 below the 10-bit
// storage HDRP renders the texture into.
constexpr double kSheenBTolerance = 1e-7;

struct Needs {
  bool splitSum = false, sheen = false, sheenB = false, f82 = false, average = false;
  bool disney = false, glass = false, glassAverage = false, zeltner = false;
  bool ltc = false;
  bool spec = false, specAverage = false;  // the dielectric's reflection alone
};

bool IsLtcMatrixMeaning(const std::string &meaning) {
  return meaning == "ltc_m00" || meaning == "ltc_m20" || meaning == "ltc_m02" ||
         meaning == "ltc_m22" || meaning == "ltc_m11";
}

Needs NeedsOf(const PresetTexture &texture) {
  Needs needs;
  for (const PresetChannel &c : texture.channels) {
    if (c.meaning == "A" || c.meaning == "B" || c.meaning == "E")
      needs.splitSum = true;
    else if (c.meaning == "sheen_E")
      needs.sheen = true;
    else if (c.meaning == "sheen_B")
      needs.sheenB = true;
    else if (c.meaning == "f82")
      needs.f82 = true;
    else if (c.meaning == "Eavg")
      needs.average = true;
    else if (c.meaning == "disney_diffuse")
      needs.disney = true;
    else if (c.meaning == "glass_E")
      needs.glass = true;
    else if (c.meaning == "glass_Eavg")
      needs.glassAverage = true;
    else if (c.meaning == "spec_E")
      needs.spec = true;
    else if (c.meaning == "spec_Eavg")
      needs.specAverage = true;
    else if (c.meaning == "zeltner_a" || c.meaning == "zeltner_b" || c.meaning == "zeltner_R")
      needs.zeltner = true;
    else if (IsLtcMatrixMeaning(c.meaning))
      needs.ltc = true;
    else if (c.meaning != "one" && c.meaning != "zero" && c.meaning != "fabric_lambert" &&
             c.meaning != "clipped_sphere")
      throw std::invalid_argument("preset channel '" + c.meaning + "' is not known");
  }
  return needs;
}

double AlphaOf(AlphaMapping mapping, double roughness, double alphaMin) {
  return std::max(AlphaFromRoughness(mapping, roughness), alphaMin);
}

// The split-sum terms {A, B} at (mu, alpha) under the texture's model: the
// exact Smith forms through table dfg's integrator, the fitted ones through
// the same panel quadrature with their G2 (albedo_quadrature.h); at alpha =
// 0 (the mirror: G2 = 1 in every form, o.h = mu) A = 1 - (1 - mu)^5 and B =
// (1 - mu)^5 exactly.
PointValue SplitSum(const PresetModel &model, double mu, double alpha) {
  if (model.fitted != FittedVisibility::kNone) {
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
  return TableNamed("dfg").Evaluate(model.TableSettings(), mu, std::sqrt(alpha));
}

// The albedo of Burley's diffuse as Unity HDRP renormalises it: its
// DisneyDiffuseNoPI divides F(mu_i) F(mu_o) by 1.03571 (29/28 rounded, the
// albedo at mu_o = 1 and perceptual roughness 1), so its albedo is table
// burley_E's (the closed form, burley_E.cpp) over 1.03571.
constexpr double kHdrpDisneyNormalisation = 1.03571;
PointValue DisneyDiffuseAlbedo(double mu_o, double perceptualRoughness) {
  PointValue v = TableNamed("burley_E").Evaluate(BakeSettings{}, mu_o, perceptualRoughness);
  v.value[0] /= kHdrpDisneyNormalisation;
  v.error[0] /= kHdrpDisneyNormalisation;
  return v;
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

// The lobe of the model's ltcLobe at the engine's roughness q (PresetLtcLobe).
LtcLobe PresetLtcLobeAt(const PresetModel &model, double q) {
  const double alpha = AlphaOf(model.alpha, q, model.alphaMin);
  switch (model.ltcLobe) {
    case PresetLtcLobe::kBurley: return BurleyLtcLobe(std::sqrt(alpha));
    case PresetLtcLobe::kSheen: return SheenLtcLobe(model.sheenVisibility, alpha);
    case PresetLtcLobe::kOrenNayar:
      return OrenNayarLtcLobe(OrenNayarVariant::kQualitative, 0.5 * kPi * alpha);
    case PresetLtcLobe::kGgx: break;
  }
  return MicrofacetLtcLobe(Ndf{NdfKind::kGgx, alpha}, model.smith);
}

// The LTC fits of a texture's (mu, roughness) grid, texel (i over the mu
// axis, j over the roughness axis) at i * roughness count + j.
std::vector<LtcTexel> FitPresetLtc(const PresetTexture &texture, int muAxis, int roughnessAxis) {
  const PresetModel &model = texture.model;
  if (model.ltcLobe == PresetLtcLobe::kGgx && model.fitted != FittedVisibility::kNone)
    throw std::invalid_argument(texture.file + ": the GGX LTC channels take an exact Smith form");
  if (muAxis < 0) throw std::invalid_argument(texture.file + ": the LTC channels need a mu axis");
  const PresetAxis &ma = texture.axes[static_cast<size_t>(muAxis)];
  const PresetAxis &ra = texture.axes[static_cast<size_t>(roughnessAxis)];
  std::vector<double> mu, roughness;
  for (int i = 0; i < ma.count; ++i) mu.push_back(ma.Quantity(i));
  for (int j = 0; j < ra.count; ++j) roughness.push_back(ra.Quantity(j));
  LtcFitSettings settings;
  settings.moments = false;  // the channels "E" and "B" integrate them
  return FitLtcGrid([&](double q) { return PresetLtcLobeAt(model, q); }, mu, roughness, settings);
}

struct AxisRoles {
  int mu = -1, roughness = -1, eta = -1;
};

AxisRoles RolesOf(const PresetTexture &texture, const Needs &needs) {
  if (texture.axes.empty() || texture.axes.size() > 3)
    throw std::invalid_argument(texture.file + ": a preset texture has one to three axes");
  AxisRoles roles;
  for (size_t a = 0; a < texture.axes.size(); ++a) {
    const std::string &quantity = texture.axes[a].quantity;
    if (quantity == "mu") roles.mu = static_cast<int>(a);
    if (quantity == "roughness") roles.roughness = static_cast<int>(a);
    if (quantity == "eta" || quantity == "1/eta") roles.eta = static_cast<int>(a);
  }
  const bool averaged = needs.average || needs.glassAverage || needs.specAverage;
  const bool dielectric = needs.glass || needs.glassAverage || needs.spec || needs.specAverage;
  // Channels of geometry alone (the clipped sphere, constants) read the
  // texture coordinates, not a lobe: any axes do (EEVEE's ltc_disk_integral).
  bool geometryOnly = true;
  for (const PresetChannel &c : texture.channels)
    geometryOnly = geometryOnly &&
                   (c.meaning == "clipped_sphere" || c.meaning == "one" || c.meaning == "zero");
  if (geometryOnly && !dielectric) return roles;
  if (roles.roughness < 0 || (roles.mu < 0 && !averaged))
    throw std::invalid_argument(texture.file +
                                ": a preset texture needs its mu and roughness axes");
  if (dielectric != (roles.eta >= 0))
    throw std::invalid_argument(
        texture.file + ": the dielectric (glass, spec) channels, and only they, take an eta axis");
  return roles;
}

// The channels of the texel at memory index (index[0], index[1], index[2])
// (an index outside an axis stands at its end: PresetAxis::Quantity), with
// their bounds. `ltc`: the texture's LTC fit over its (mu, roughness) grid
// (FitPresetLtc), where a channel reads one.
void TexelChannels(const PresetTexture &texture, const Needs &needs, const AxisRoles &roles,
                   const std::vector<LtcTexel> &ltc, const int index[3], double *values,
                   double *errors) {
  const PresetModel &model = texture.model;
  // The texel in memory at index i holds the axis texel i, or N - 1 - i
  // when the axis runs from u = 1.
  const auto axisTexel = [&](int axis) {
    const PresetAxis &a = texture.axes[static_cast<size_t>(axis)];
    return a.reversed ? a.count - 1 - index[axis] : index[axis];
  };
  const auto quantity = [&](int axis) {
    return texture.axes[static_cast<size_t>(axis)].Quantity(axisTexel(axis));
  };
  // The settings of the tables the channels read: the model's.
  const BakeSettings settings = model.TableSettings();
  const double roughness = roles.roughness >= 0 ? quantity(roles.roughness) : 0.0;
  const double mu = roles.mu >= 0 ? quantity(roles.mu) : 0.0;
  double eta = 1.0;
  if (roles.eta >= 0) {
    const double q = quantity(roles.eta);
    eta = texture.axes[static_cast<size_t>(roles.eta)].quantity == "1/eta" ? 1.0 / q : q;
  }
  const double alpha = AlphaOf(model.alpha, roughness, model.alphaMin);
  PointValue split, sheen, sheenB, f82, average, disney, glass, glassAverage, spec, specAverage;
  if (needs.sheenB) {
    const double sheenAlpha = AlphaFromRoughness(model.sheenAlpha, roughness);
    const SheenIntegral b = IntegrateSheenSchlickWeightedAdaptive(model.sheenVisibility, sheenAlpha,
                                                                  mu, kSheenBTolerance);
    sheenB.value[0] = b.value;
    sheenB.error[0] = b.bound;
  }
  if (needs.disney) disney = DisneyDiffuseAlbedo(mu, roughness);
  if (needs.splitSum) split = SplitSum(model, mu, alpha);
  // The sheen's roughness with the engine's clamp of its alpha.
  const double sheenRoughness = model.sheenAlpha == AlphaMapping::kSquared
                                    ? std::max(roughness, std::sqrt(model.sheenAlphaMin))
                                    : std::max(roughness, model.sheenAlphaMin);
  if (needs.sheen) sheen = TableNamed("sheen_E").Evaluate(settings, mu, sheenRoughness);
  if (needs.f82) f82 = TableNamed("f82").Evaluate(settings, mu, std::sqrt(alpha));
  if (needs.average) average = TableNamed("Eavg").Evaluate(settings, std::sqrt(alpha), 0.0);
  if (needs.glass || needs.glassAverage) {
    // The engine's own index-matched interface: no lobe, albedo 1.
    if (std::abs(eta - 1.0) < model.unitEtaWindow) {
      glass.value[0] = glassAverage.value[0] = 1.0;
    } else {
      if (needs.glass)
        glass = TableNamed("glass_E").Evaluate3D(settings, mu, std::sqrt(alpha), eta);
      if (needs.glassAverage)
        glassAverage = TableNamed("glass_Eavg").Evaluate(settings, std::sqrt(alpha), eta);
    }
  }
  if (needs.spec) spec = TableNamed("spec_E").Evaluate3D(settings, mu, std::sqrt(alpha), eta);
  if (needs.specAverage)
    specAverage = TableNamed("spec_Eavg").Evaluate(settings, std::sqrt(alpha), eta);
  // The single-valued meanings and the integral each reads.
  const std::pair<const char *, const PointValue *> kSingle[] = {{"sheen_E", &sheen},
                                                                 {"f82", &f82},
                                                                 {"Eavg", &average},
                                                                 {"sheen_B", &sheenB},
                                                                 {"disney_diffuse", &disney},
                                                                 {"glass_E", &glass},
                                                                 {"glass_Eavg", &glassAverage},
                                                                 {"spec_E", &spec},
                                                                 {"spec_Eavg", &specAverage}};
  for (size_t c = 0; c < texture.channels.size(); ++c) {
    const PresetChannel &channel = texture.channels[c];
    double value = 0.0, error = 0.0;
    if (channel.meaning == "A" || channel.meaning == "B") {
      const int k = channel.meaning == "A" ? 0 : 1;
      value = split.value[k];
      error = split.error[k];
    } else if (channel.meaning == "E") {
      value = split.value[0] + split.value[1];
      error = split.error[0] + split.error[1];
    } else if (channel.meaning == "fabric_lambert") {
      // HDRP's FabricLambertNoPI: lerp(1, 1/2, alpha), alpha = roughness^2.
      value = 1.0 - 0.5 * alpha;
    } else if (channel.meaning == "one") {
      value = 1.0;
    } else if (needs.zeltner && channel.meaning.rfind("zeltner_", 0) == 0) {
      // The published table, at alpha = the roughness axis.
      const std::array<double, 3> zeltner = ZeltnerSheenLtc(mu, roughness);
      value = zeltner[channel.meaning == "zeltner_a" ? 0 : channel.meaning == "zeltner_b" ? 1 : 2];
    } else if (IsLtcMatrixMeaning(channel.meaning)) {
      // The fit is the value (its bound 0; what it is worth is the lobe
      // error that eval --table ltc_ggx states).
      const int count = texture.axes[static_cast<size_t>(roles.roughness)].count;
      const LtcMatrix &m =
          ltc[static_cast<size_t>(axisTexel(roles.mu)) * count + axisTexel(roles.roughness)].minv;
      // Scaled so that m22 = 1 (HDRP): the fit's m22 > 0 (det M^-1 > 0
      // and m11 = 1 do not give it; a texel without it is refused).
      value = channel.meaning == "ltc_m00"   ? m.m00
              : channel.meaning == "ltc_m20" ? m.m20
              : channel.meaning == "ltc_m02" ? m.m02
              : channel.meaning == "ltc_m22" ? m.m22
                                             : 1.0;
      if (model.ltcScale == PresetLtcScale::kUnitM22) {
        if (!(m.m22 > 0.0))
          throw std::runtime_error(texture.file + ": the fitted m22 is " + FormatDouble(m.m22) +
                                   " at mu = " + FormatDouble(mu) + ", roughness = " +
                                   FormatDouble(roughness) + ": M^-1 cannot be scaled to m22 = 1");
        value /= m.m22;  // each entry over m22, correctly rounded
      }
    } else if (channel.meaning == "clipped_sphere") {
      const double u = texture.axes[0].Coordinate(axisTexel(0));
      const double v = texture.axes.size() > 1 ? texture.axes[1].Coordinate(axisTexel(1)) : 0.0;
      value = ClippedSphere(2.0 * u - 1.0, v);
    } else {
      for (const auto &[meaning, integral] : kSingle)
        if (channel.meaning == meaning) {
          value = integral->value[0];
          error = integral->error[0];
        }
    }
    const double stored = channel.scale * value + channel.offset;
    values[c] = std::clamp(stored, channel.clampMin, channel.clampMax);
    errors[c] = std::fabs(channel.scale) * error +
                (channel.clampIsValue ? 0.0 : std::abs(stored - values[c]));
  }
}

// The seconds one texel of a texture with LTC channels costs in
// BakePresetTexture: its fit as FitLtcGrid starts it, from the fit of its
// neighbour one roughness step up (fitted first, untimed, from the texel
// two steps up: a fit from the identity costs several times a warm one),
// and its other channels as TexelChannels computes them. The lobe is built
// once a roughness column in the bake: untimed.
double SecondsOfLtcTexel(const PresetTexture &texture, const int index[3]) {
  using Clock = std::chrono::steady_clock;
  const Needs needs = NeedsOf(texture);
  const AxisRoles roles = RolesOf(texture, needs);
  if (texture.model.ltcLobe == PresetLtcLobe::kGgx &&
      texture.model.fitted != FittedVisibility::kNone)
    throw std::invalid_argument(texture.file + ": the GGX LTC channels take an exact Smith form");
  const PresetAxis &ma = texture.axes[static_cast<size_t>(roles.mu)];
  const PresetAxis &ra = texture.axes[static_cast<size_t>(roles.roughness)];
  const int i = index[roles.mu], j = index[roles.roughness];
  // The texels above in roughness (Quantity clamps an index past the end).
  const int up = ra.Quantity(std::min(j + 1, ra.count - 1)) >= ra.Quantity(j) ? 1 : -1;
  const double mu = ma.Quantity(i);
  LtcFitSettings settings;
  settings.moments = false;
  LtcMatrix start;
  for (int step : {2, 1})
    start =
        FitLtcTexel(PresetLtcLobeAt(texture.model, ra.Quantity(j + step * up)), mu, start, settings)
            .minv;
  const LtcLobe lobe = PresetLtcLobeAt(texture.model, ra.Quantity(j));
  PresetTexture others = texture;
  others.channels.clear();
  for (const PresetChannel &c : texture.channels)
    if (!IsLtcMatrixMeaning(c.meaning)) others.channels.push_back(c);
  std::vector<double> values(others.channels.size()), errors(others.channels.size());
  const Clock::time_point t0 = Clock::now();
  (void)FitLtcTexel(lobe, mu, start, settings);
  if (!others.channels.empty()) {
    const Needs otherNeeds = NeedsOf(others);
    TexelChannels(others, otherNeeds, RolesOf(others, otherNeeds), {}, index, values.data(),
                  errors.data());
  }
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

void PresetTexelValues(const PresetTexture &texture, const int index[3], double *values,
                       double *errors) {
  const Needs needs = NeedsOf(texture);
  if (needs.ltc)
    throw std::invalid_argument(texture.file +
                                ": its LTC channels are fitted over the whole grid at once, not "
                                "per texel");
  TexelChannels(texture, needs, RolesOf(texture, needs), {}, index, values, errors);
}

Table BakePresetTexture(const PresetTexture &texture, const std::string &presetName,
                        const CancellationToken *cancellation,
                        const std::function<void(double fraction)> &progress) {
  const Needs needs = NeedsOf(texture);
  const AxisRoles roles = RolesOf(texture, needs);

  Table table;
  // The file's name without its extension ("LtcData.BRDF_GGX" of
  // LtcData.BRDF_GGX.cs).
  table.name = texture.file.substr(0, texture.file.rfind('.'));
  const auto tableAxis = [](const PresetAxis &axis, const char *name) {
    Axis out = LinearAxis(name, 0.0, 1.0, axis.count);
    if (axis.placement == TexelPlacement::kEdges && axis.count > 1) {
      const double h = 0.5 / (axis.count - 1);
      out.min = -h;
      out.max = 1.0 + h;
    }
    return out;
  };
  // A reversed axis runs from u = 1 in memory: the table's coordinate is 1 - u.
  table.x = tableAxis(texture.axes[0], texture.axes[0].reversed ? "1-u" : "u");
  if (texture.axes.size() > 1)
    table.y = tableAxis(texture.axes[1], texture.axes[1].reversed ? "1-v" : "v");
  if (texture.axes.size() > 2)
    table.z = tableAxis(texture.axes[2], texture.axes[2].reversed ? "1-w" : "w");
  table.channels = static_cast<int>(texture.channels.size());
  static const char *const kNames[] = {"R", "G", "B", "A"};
  for (int c = 0; c < table.channels; ++c) table.channelNames.push_back(kNames[c % 4]);
  table.values.assign(table.texelCount() * table.channels, 0.0);
  table.errors.assign(table.values.size(), 0.0);

  const int width = table.width(), height = table.height(), depth = table.depth();
  const std::vector<LtcTexel> ltc =
      needs.ltc ? FitPresetLtc(texture, roles.mu, roles.roughness) : std::vector<LtcTexel>{};
  // One task per row of x; rows of every slice in turn.
  std::mutex progressMutex;
  size_t rowsDone = 0;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height * depth), [&](const tbb::blocked_range<int> &rows) {
        for (int row = rows.begin(); row != rows.end(); ++row) {
          if (cancellation) cancellation->ThrowIfCancelled();
          const int iy = row % height, iz = row / height;
          for (int ix = 0; ix < width; ++ix) {
            const int index[3] = {ix, iy, iz};
            const size_t at = table.index(ix, iy, iz, 0);
            TexelChannels(texture, needs, roles, ltc, index, &table.values[at], &table.errors[at]);
          }
        }
        if (progress) {
          std::lock_guard<std::mutex> lock(progressMutex);
          rowsDone += rows.size();
          progress(static_cast<double>(rowsDone) / (height * depth));
        }
      });

  table.metadata = {{"table", table.name},
                    {"preset", presetName},
                    {"presetSource", texture.source},
                    {"sampling", texture.sampling},
                    {"axisX", DescribeAxis(table.x)},
                    {"axisY", table.is2D() ? DescribeAxis(table.y) : "none (1D table)"}};
  if (table.is3D()) table.metadata.emplace_back("axisZ", DescribeAxis(table.z));
  std::string layout;
  for (int c = 0; c < table.channels; ++c) {
    const PresetChannel &channel = texture.channels[static_cast<size_t>(c)];
    layout += (c ? ", " : "") + table.channelNames[static_cast<size_t>(c)] + " = " +
              (channel.scale != 1.0 ? FormatDouble(channel.scale) + " " : "") + channel.meaning +
              (channel.offset != 0.0 ? " + " + FormatDouble(channel.offset) : "");
  }
  table.metadata.emplace_back("channelLayout", layout);
  return table;
}

BakeEstimate EstimatePresetBake(const Preset &preset, double secondsPerTexture) {
  std::vector<EstimatedWork> work;
  for (const PresetTexture &texture : preset.textures) {
    EstimatedWork w;
    for (size_t a = 0; a < texture.axes.size() && a < 3; ++a) w.counts[a] = texture.axes[a].count;
    if (!NeedsOf(texture).ltc) {
      w.evaluateTexel = [&texture](int i, int j, int k) {
        const int index[3] = {i, j, k};
        double values[8], errors[8];
        PresetTexelValues(texture, index, values, errors);
      };
    } else {
      w.timeTexel = [&texture](int i, int j, int k) {
        const int index[3] = {i, j, k};
        return SecondsOfLtcTexel(texture, index);
      };
    }
    work.push_back(std::move(w));
  }
  return EstimateWork(work, secondsPerTexture);
}

}  // namespace lutbake
