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

#include "channel_source.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/ltc_fit.h"

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

// The LTC fits of a texture's (mu, roughness) grid, texel (i over the mu
// axis, j over the roughness axis) at i * roughness count + j.
std::vector<LtcTexel> FitPresetLtc(const PresetTexture &texture, const PresetChannelPlan &plan) {
  const PresetAxis &ma = texture.axes[static_cast<size_t>(plan.muAxis)];
  const PresetAxis &ra = texture.axes[static_cast<size_t>(plan.roughnessAxis)];
  std::vector<double> mu, roughness;
  for (int i = 0; i < ma.count; ++i) mu.push_back(ma.Quantity(i));
  for (int j = 0; j < ra.count; ++j) roughness.push_back(ra.Quantity(j));
  LtcFitSettings settings;
  settings.moments = false;  // the channels "E" and "B" integrate them
  return FitLtcGrid([&](double q) { return plan.LobeAt(q); }, mu, roughness, settings);
}

// The channels of the texel at memory index (index[0], index[1], index[2])
// (an index outside an axis stands at its end: PresetAxis::Quantity), with
// their bounds. `ltc`: the texture's LTC fit over its (mu, roughness) grid
// (FitPresetLtc), where a channel reads one.
void TexelChannels(const PresetTexture &texture, const PresetChannelPlan &plan,
                   const std::vector<LtcTexel> &ltc, const int index[3], double *values,
                   double *errors) {
  // The texel in memory at index i holds the axis texel i, or N - 1 - i
  // when the axis runs from u = 1.
  const auto axisTexel = [&](int axis) {
    const PresetAxis &a = texture.axes[static_cast<size_t>(axis)];
    return a.reversed ? a.count - 1 - index[axis] : index[axis];
  };
  const auto quantity = [&](int axis) {
    return texture.axes[static_cast<size_t>(axis)].Quantity(axisTexel(axis));
  };
  PresetTexel texel;
  texel.model = &texture.model;
  // The settings of the tables the channels read: the model's.
  texel.settings = texture.model.TableSettings();
  texel.roughness = plan.roughnessAxis >= 0 ? quantity(plan.roughnessAxis) : 0.0;
  texel.mu = plan.muAxis >= 0 ? quantity(plan.muAxis) : 0.0;
  if (plan.etaAxis >= 0) {
    const double q = quantity(plan.etaAxis);
    texel.eta = texture.axes[static_cast<size_t>(plan.etaAxis)].quantity == "1/eta" ? 1.0 / q : q;
  }
  texel.alpha = PresetAlpha(texture.model, texel.roughness);
  texel.u = texture.axes[0].Coordinate(axisTexel(0));
  if (texture.axes.size() > 1) texel.v = texture.axes[1].Coordinate(axisTexel(1));
  const LtcMatrix *fit = nullptr;
  if (!ltc.empty()) {
    const int count = texture.axes[static_cast<size_t>(plan.roughnessAxis)].count;
    fit = &ltc[static_cast<size_t>(axisTexel(plan.muAxis)) * count + axisTexel(plan.roughnessAxis)]
               .minv;
  }
  plan.Channels(texel, fit, values, errors);
}

// The seconds one texel of a texture with LTC channels costs in
// BakePresetTexture: its fit as FitLtcGrid starts it, from the fit of its
// neighbour one roughness step up (fitted first, untimed, from the texel
// two steps up: a fit from the identity costs several times a warm one),
// and its other channels as TexelChannels computes them. The lobe is built
// once a roughness column in the bake: untimed.
double SecondsOfLtcTexel(const PresetTexture &texture, const int index[3]) {
  using Clock = std::chrono::steady_clock;
  const PresetChannelPlan plan(texture);
  const PresetAxis &ma = texture.axes[static_cast<size_t>(plan.muAxis)];
  const PresetAxis &ra = texture.axes[static_cast<size_t>(plan.roughnessAxis)];
  const int i = index[plan.muAxis], j = index[plan.roughnessAxis];
  // The texels above in roughness (Quantity clamps an index past the end).
  const int up = ra.Quantity(std::min(j + 1, ra.count - 1)) >= ra.Quantity(j) ? 1 : -1;
  const double mu = ma.Quantity(i);
  LtcFitSettings settings;
  settings.moments = false;
  LtcMatrix start;
  for (int step : {2, 1})
    start = FitLtcTexel(plan.LobeAt(ra.Quantity(j + step * up)), mu, start, settings).minv;
  const LtcLobe lobe = plan.LobeAt(ra.Quantity(j));
  const PresetTexture others = plan.WithoutFit();
  std::vector<double> values(others.channels.size()), errors(others.channels.size());
  const Clock::time_point t0 = Clock::now();
  (void)FitLtcTexel(lobe, mu, start, settings);
  if (!others.channels.empty())
    TexelChannels(others, PresetChannelPlan(others), {}, index, values.data(), errors.data());
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

void PresetTexelValues(const PresetTexture &texture, const int index[3], double *values,
                       double *errors) {
  const PresetChannelPlan plan(texture);
  if (plan.Fitted())
    throw std::invalid_argument(texture.file +
                                ": its LTC channels are fitted over the whole grid at once, not "
                                "per texel");
  TexelChannels(texture, plan, {}, index, values, errors);
}

Table BakePresetTexture(const PresetTexture &texture, const std::string &presetName,
                        const CancellationToken *cancellation,
                        const std::function<void(double fraction)> &progress) {
  const PresetChannelPlan plan(texture);

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
      plan.Fitted() ? FitPresetLtc(texture, plan) : std::vector<LtcTexel>{};
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
            TexelChannels(texture, plan, ltc, index, &table.values[at], &table.errors[at]);
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
    if (!PresetChannelPlan(texture).Fitted()) {
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
