// Baking a preset's texture: the engine's coordinates of every texel, the
// model's alpha there, and the channels from lutbake's integrators.
#include "lutbake/presets/preset.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "lutbake/formats/writer.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/sheen_quadrature.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

const char *ToString(PresetMapping mapping) {
  switch (mapping) {
    case PresetMapping::kLinear: return "u";
    case PresetMapping::kSquare: return "u^2";
    case PresetMapping::kOneMinusSquare: return "1 - u^2";
    case PresetMapping::kIorOfF0Root4: return "(1 + u^2) / (1 - u^2)";
  }
  return "?";
}

const char *ToString(TexelPlacement placement) {
  return placement == TexelPlacement::kCentres ? "centres" : "edges";
}

const char *ToString(PresetVisibility visibility) {
  switch (visibility) {
    case PresetVisibility::kCorrelated: return "smith-correlated";
    case PresetVisibility::kSeparable: return "smith-separable";
    case PresetVisibility::kSchlickGgx: return "schlick-ggx k = alpha / 2";
    case PresetVisibility::kSmithJointApprox: return "smith-joint-approx a = alpha";
  }
  return "?";
}

const char *ToString(PresetAlpha alpha) {
  return alpha == PresetAlpha::kSquared ? "alpha = roughness^2" : "alpha = roughness";
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
  bool disney = false, glass = false, glassAverage = false;
};

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
    else if (c.meaning != "one" && c.meaning != "zero" && c.meaning != "fabric_lambert")
      throw std::invalid_argument("preset channel '" + c.meaning + "' is not known");
  }
  return needs;
}

double AlphaOf(PresetAlpha mapping, double roughness, double alphaMin) {
  const double alpha = mapping == PresetAlpha::kSquared ? roughness * roughness : roughness;
  return std::max(alpha, alphaMin);
}

// The split-sum terms {A, B} at (mu, alpha) under the texture's model: the
// exact Smith forms through table dfg's integrator, the fitted ones through
// the same panel quadrature with their G2 (albedo_quadrature.h); at alpha =
// 0 (the mirror: G2 = 1 in every form, o.h = mu) A = 1 - (1 - mu)^5 and B =
// (1 - mu)^5 exactly.
PointValue SplitSum(const PresetModel &model, double mu, double alpha) {
  if (model.visibility == PresetVisibility::kSchlickGgx ||
      model.visibility == PresetVisibility::kSmithJointApprox) {
    PointValue v;
    v.quadrature = true;
    if (alpha == 0.0) {
      const double fc = std::pow(1.0 - mu, 5.0);
      v.value[0] = 1.0 - fc;
      v.value[1] = fc;
      v.exact = true;
      return v;
    }
    const SplitSumQuadrature q = IntegrateFittedSplitSumQuadrature(
        alpha,
        model.visibility == PresetVisibility::kSchlickGgx ? FittedVisibility::kSchlickGgx
                                                          : FittedVisibility::kSmithJointApprox,
        mu, kDefaultQuadratureTolerance);
    if (!q.converged)
      throw std::runtime_error("the fitted split sum did not converge at mu = " + FormatDouble(mu) +
                               ", alpha = " + FormatDouble(alpha));
    v.value[0] = q.A;
    v.value[1] = q.B;
    v.error[0] = q.boundA;
    v.error[1] = q.boundB;
    return v;
  }
  BakeSettings settings;
  settings.smith = model.visibility == PresetVisibility::kSeparable ? SmithForm::kSeparable
                                                                    : SmithForm::kCorrelated;
  return TableNamed("dfg").Evaluate(settings, mu, std::sqrt(alpha));
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

}  // namespace

namespace {

// Which axis drives mu, roughness and eta (-1: none); throws when the
// texture's channels and axes do not fit together.
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
  const bool averaged = needs.average || needs.glassAverage;
  if (roles.roughness < 0 || (roles.mu < 0 && !averaged))
    throw std::invalid_argument(texture.file +
                                ": a preset texture needs its mu and roughness axes");
  if ((needs.glass || needs.glassAverage) != (roles.eta >= 0))
    throw std::invalid_argument(texture.file +
                                ": the glass channels, and only they, take an eta axis");
  return roles;
}

// The channels of the texel at memory index (ix, iy, iz) (an index outside
// the axis stands at its end: PresetAxis::Quantity), with their bounds.
void TexelChannels(const PresetTexture &texture, const Needs &needs, const AxisRoles &roles,
                   const int index[3], double *values, double *errors) {
  const PresetModel &model = texture.model;
  // The texel in memory at index i holds the axis texel i, or N - 1 - i
  // when the axis runs from u = 1.
  const auto quantity = [&](int axis) {
    const PresetAxis &a = texture.axes[static_cast<size_t>(axis)];
    return a.Quantity(a.reversed ? a.count - 1 - index[axis] : index[axis]);
  };
  // The settings of the tables the channels read: the model's.
  BakeSettings microfacetSettings;
  microfacetSettings.smith = model.visibility == PresetVisibility::kSeparable
                                 ? SmithForm::kSeparable
                                 : SmithForm::kCorrelated;
  BakeSettings sheenSettings;
  sheenSettings.sheenVisibility = model.sheenVisibility;
  sheenSettings.sheenAlpha =
      model.sheenAlpha == PresetAlpha::kSquared ? SheenAlpha::kSquared : SheenAlpha::kLinear;
  const double roughness = quantity(roles.roughness);
  const double mu = roles.mu >= 0 ? quantity(roles.mu) : 0.0;
  double eta = 1.0;
  if (roles.eta >= 0) {
    const double q = quantity(roles.eta);
    eta = texture.axes[static_cast<size_t>(roles.eta)].quantity == "1/eta" ? 1.0 / q : q;
  }
  const double alpha = AlphaOf(model.alpha, roughness, model.alphaMin);
  PointValue split, sheen, sheenB, f82, average, disney, glass, glassAverage;
  if (needs.sheenB) {
    const double sheenAlpha =
        model.sheenAlpha == PresetAlpha::kSquared ? roughness * roughness : roughness;
    const SheenIntegral b = IntegrateSheenSchlickWeightedAdaptive(model.sheenVisibility, sheenAlpha,
                                                                  mu, kSheenBTolerance);
    sheenB.value[0] = b.value;
    sheenB.error[0] = b.bound;
  }
  if (needs.disney) disney = DisneyDiffuseAlbedo(mu, roughness);
  if (needs.splitSum) split = SplitSum(model, mu, alpha);
  if (needs.sheen) sheen = TableNamed("sheen_E").Evaluate(sheenSettings, mu, roughness);
  if (needs.f82) f82 = TableNamed("f82").Evaluate(microfacetSettings, mu, std::sqrt(alpha));
  if (needs.average)
    average = TableNamed("Eavg").Evaluate(microfacetSettings, std::sqrt(alpha), 0.0);
  if (needs.glass || needs.glassAverage) {
    // The engine's own index-matched interface: no lobe, albedo 1.
    if (std::abs(eta - 1.0) < model.unitEtaWindow) {
      glass.value[0] = glassAverage.value[0] = 1.0;
    } else {
      if (needs.glass)
        glass = TableNamed("glass_E").Evaluate3D(microfacetSettings, mu, std::sqrt(alpha), eta);
      if (needs.glassAverage)
        glassAverage = TableNamed("glass_Eavg").Evaluate(microfacetSettings, std::sqrt(alpha), eta);
    }
  }
  // The single-valued meanings and the integral each reads.
  const std::pair<const char *, const PointValue *> kSingle[] = {
      {"sheen_E", &sheen},          {"f82", &f82},
      {"Eavg", &average},           {"sheen_B", &sheenB},
      {"disney_diffuse", &disney},  {"glass_E", &glass},
      {"glass_Eavg", &glassAverage}};
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
    } else {
      for (const auto &[meaning, integral] : kSingle)
        if (channel.meaning == meaning) {
          value = integral->value[0];
          error = integral->error[0];
        }
    }
    const double stored = channel.scale * value + channel.offset;
    values[c] = std::min(stored, channel.clampMax);
    errors[c] = std::fabs(channel.scale) * error + (stored - values[c]);
  }
}

}  // namespace

void PresetTexelValues(const PresetTexture &texture, const int index[3], double *values,
                       double *errors) {
  const Needs needs = NeedsOf(texture);
  TexelChannels(texture, needs, RolesOf(texture, needs), index, values, errors);
}

Table BakePresetTexture(const PresetTexture &texture, const std::string &presetName,
                        const CancellationToken *cancellation) {
  const Needs needs = NeedsOf(texture);
  const AxisRoles roles = RolesOf(texture, needs);

  Table table;
  table.name = texture.file.substr(0, texture.file.find('.'));
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
  // One task per row of x; rows of every slice in turn.
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height * depth), [&](const tbb::blocked_range<int> &rows) {
        for (int row = rows.begin(); row != rows.end(); ++row) {
          if (cancellation) cancellation->ThrowIfCancelled();
          const int iy = row % height, iz = row / height;
          for (int ix = 0; ix < width; ++ix) {
            const int index[3] = {ix, iy, iz};
            const size_t at = table.index(ix, iy, iz, 0);
            TexelChannels(texture, needs, roles, index, &table.values[at], &table.errors[at]);
          }
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

}  // namespace lutbake
