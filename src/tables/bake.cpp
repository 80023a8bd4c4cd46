#include "lutbake/tables/bake.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "lutbake/integrators/replicated_integrator.h"
#include "sampled_texel.h"

#ifndef LUTBAKE_VERSION
#define LUTBAKE_VERSION "unknown"
#endif

namespace lutbake {

const char *LutbakeVersion() { return LUTBAKE_VERSION; }

std::string_view ToString(Estimator estimator) {
  switch (estimator) {
    case Estimator::kVisibleNormal: return "vndf";
    case Estimator::kVisibleNormalRandom: return "vndf-random";
    case Estimator::kNdf: return "ndf";
    case Estimator::kCosine: return "cosine";
    case Estimator::kUniform: return "uniform";
    case Estimator::kQuadrature: return "quadrature";
    case Estimator::kAdaptiveQuadrature: return "adaptive";
  }
  return "?";
}

bool ParseEstimator(std::string_view name, Estimator *estimator) {
  for (Estimator e : kAllEstimators)
    if (name == ToString(e)) {
      *estimator = e;
      return true;
    }
  return false;
}

Axis MuAxis(int count) { return LinearAxis("mu", 0.0, 1.0, count); }
Axis RoughnessAxis(int count) { return LinearAxis("perceptualRoughness", 0.0, 1.0, count); }

void FresnelAxes(FresnelModel model, int count, Axis *x, Axis *y) {
  *y = LinearAxis("", 0.0, 1.0, 1);
  switch (model) {
    case FresnelModel::kSchlick: *x = LinearAxis("F0", 0.0, 1.0, count); break;
    // Relative IOR from 1 (no interface) to 3: every common dielectric,
    // diamond (2.42) included, lies inside.
    case FresnelModel::kDielectric: *x = LinearAxis("eta", 1.0, 3.0, count); break;
    // Complex IOR eta + i k: metals across the visible spectrum have
    // eta in (0, 4) and k in (0, 10) (gold, copper, aluminium, iron, ...).
    case FresnelModel::kConductor:
      *x = LinearAxis("eta", 0.0, 4.0, count);
      *y = LinearAxis("k", 0.0, 10.0, count);
      break;
    // F82 tint: F0 and the tint, both reflectances in [0, 1].
    case FresnelModel::kF82:
      *x = LinearAxis("F0", 0.0, 1.0, count);
      *y = LinearAxis("tint", 0.0, 1.0, count);
      break;
  }
}

void DefaultAxes(const TableDefinition &table, const BakeSettings &s, Axis *x, Axis *y) {
  table.Axes(s, s.SizeFor(table.Name(), table.DefaultSize()), x, y);
}

Axis DefaultDepthAxis(const TableDefinition &table, const BakeSettings &s) {
  Axis z;
  table.DepthAxis(s, s.depthSize > 0 ? s.depthSize : table.DefaultDepth(), &z);
  return z;
}

void DefaultAxes(const TableDefinition &table, const BakeSettings &s, Axis *x, Axis *y, Axis *z) {
  DefaultAxes(table, s, x, y);
  *z = DefaultDepthAxis(table, s);
}

PointValue EvaluateTexel(const TableDefinition &definition, const BakeSettings &s,
                         const Table &table, int ix, int iy, int iz) {
  const double x = table.x.TexelCenter(ix), y = table.y.TexelCenter(iy);
  return table.is3D() ? definition.Evaluate3D(s, x, y, table.z.TexelCenter(iz))
                      : definition.Evaluate(s, x, y);
}

std::string DescribeEstimator(const TableDefinition &definition, const BakeSettings &s) {
  if (!definition.Sampled() || IsQuadrature(s.estimator))
    return definition.QuadratureDescription(s);
  const bool random = PointSetOf(s.estimator) == PointSet::kIndependentRandom;
  std::string text =
      std::string(ToString(s.estimator)) +
      (random ? " with independent random points" : " with Owen-scrambled Sobol points");
  if (const std::string note = definition.SamplerNote(s); !note.empty()) text += "; " + note;
  if (s.tolerance > 0.0 && s.allowQuadratureSwitch)
    text += "; texels for which the quadrature is cheaper switch to it";
  return text;
}

Table BakeTable(const TableDefinition &definition, const BakeSettings &s,
                const ProgressFn &progress, BakeStats *statsOut) {
  Axis x, y, z;
  DefaultAxes(definition, s, &x, &y, &z);
  return BakeTableOn(definition, s, x, y, z, progress, statsOut);
}

Table BakeTableOn(const TableDefinition &definition, const BakeSettings &s, const Axis &x,
                  const Axis &y, const ProgressFn &progress, BakeStats *statsOut) {
  return BakeTableOn(definition, s, x, y, DefaultDepthAxis(definition, s), progress, statsOut);
}

Table BakeTableOn(const TableDefinition &definition, const BakeSettings &s, const Axis &x,
                  const Axis &y, const Axis &z, const ProgressFn &progress, BakeStats *statsOut) {
  const auto start = std::chrono::steady_clock::now();
  Table table;
  table.definition = &definition;
  table.x = x;
  table.y = y;
  table.z = z;
  table.channels = definition.Channels();
  table.channelNames = definition.ChannelNames();
  const size_t texels = table.texelCount();
  table.values.assign(texels * table.channels, 0.0);
  table.errors.assign(texels * table.channels, 0.0);

  std::vector<uint64_t> texelSamples(texels, 0), texelEvaluations(texels, 0);
  std::vector<uint8_t> texelQuadrature(texels, 0);
  std::atomic<size_t> done{0};
  // A fitted table bakes all its texels at once (table_definition.h); the
  // loop below then has none to run.
  uint64_t wholeEvaluations = 0;
  if (definition.BakedWhole()) {
    wholeEvaluations = definition.BakeWhole(s, &table);
    if (progress) progress(1.0);
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, definition.BakedWhole() ? 0 : texels),
                    [&](const tbb::blocked_range<size_t> &r) {
                      for (size_t k = r.begin(); k != r.end(); ++k) {
                        // Thrown out of parallel_for, which cancels the other tasks.
                        if (s.cancellation) s.cancellation->ThrowIfCancelled();
                        // Column by column (k runs down each column of constant mu): the
                        // quadrature's azimuthal nodes depend on mu only, and a thread
                        // that stays in a column reuses them. Each texel is computed
                        // alone, so the order changes nothing in the values.
                        // (A 3D table: slice by slice, each as a 2D table.)
                        const size_t slice = static_cast<size_t>(table.width()) * table.height();
                        const int iz = static_cast<int>(k / slice);
                        const size_t inSlice = k % slice;
                        const int ix = static_cast<int>(inSlice / table.height());
                        const int iy = static_cast<int>(inSlice % table.height());
                        const size_t t = iz * slice + static_cast<size_t>(iy) * table.width() + ix;
                        const PointValue texel = EvaluateTexel(definition, s, table, ix, iy, iz);
                        for (int c = 0; c < table.channels; ++c) {
                          table.values[t * table.channels + c] = texel.value[c];
                          table.errors[t * table.channels + c] = texel.error[c];
                        }
                        texelSamples[t] = texel.samples;
                        texelEvaluations[t] = texel.evaluations;
                        texelQuadrature[t] = texel.quadrature ? 1 : 0;
                      }
                      const size_t now = done.fetch_add(r.size()) + r.size();
                      if (progress)
                        progress(static_cast<double>(now) / static_cast<double>(texels));
                    });

  BakeStats stats;
  stats.evaluations = wholeEvaluations;
  for (size_t t = 0; t < texels; ++t) {
    stats.samples += texelSamples[t];
    stats.maxTexelSamples = std::max(stats.maxTexelSamples, texelSamples[t]);
    stats.evaluations += texelEvaluations[t];
    stats.quadratureTexels += texelQuadrature[t];
    if (s.tolerance > 0.0)
      for (int c = 0; c < table.channels; ++c)
        if (!(table.errors[t * table.channels + c] <= s.tolerance)) {
          ++stats.unconverged;
          break;
        }
  }

  // Tables that take the sampled estimators and --tolerance (F_avg does not).
  const bool albedo = definition.Sampled();
  const bool sampled = albedo && !IsQuadrature(s.estimator);
  const bool tolerance = sampled && s.tolerance > 0.0;
  const int replicates =
      tolerance ? std::clamp(s.replicates, 1, 64)
                : static_cast<int>(std::min<uint64_t>(
                      s.replicates, std::max<uint64_t>(1, definition.SamplesPerTexel(s))));
  const bool random = PointSetOf(s.estimator) == PointSet::kIndependentRandom;
  auto &m = table.metadata;
  m.emplace_back("table", definition.Name());
  for (auto &entry : definition.ModelMetadata(s)) m.push_back(std::move(entry));
  m.emplace_back("axisX", DescribeAxis(table.x));
  m.emplace_back("axisY", table.is2D() ? DescribeAxis(table.y) : "none (1D table)");
  if (table.is3D()) m.emplace_back("axisZ", DescribeAxis(table.z));
  m.emplace_back("alpha", definition.AlphaMetadata(s));
  std::string convention =
      "texel i of N holds the value at u = (i + 0.5) / N, mapped linearly onto [min, max]; "
      "y = 0 first";
  if (table.is3D())
    convention +=
        "; the third axis z is outermost: slices of constant z follow one another (EXR: stacked "
        "along the image's y, slice z = 0 first), values[((z * height + y) * width + x) * "
        "channels + c]";
  if (table.x.listed() || table.y.listed() || table.z.listed())
    convention +=
        "; an axis described as 'values [...]' holds texel i at exactly its i-th value, and "
        "lookups interpolate linearly in that value between neighbouring texels";
  m.emplace_back("texelConvention", convention);
  m.emplace_back("channelLayout", definition.ChannelLayout());
  m.emplace_back("estimator", DescribeEstimator(definition, s));
  m.emplace_back("tolerance",
                 !albedo             ? "none"
                 : s.tolerance > 0.0 ? FormatDouble(s.tolerance)
                 : s.estimator == Estimator::kQuadrature
                     ? FormatDouble(kDefaultQuadratureTolerance) + " (the default: float32-exact)"
                     : "none");
  m.emplace_back("samplesPerTexel",
                 !sampled    ? "n/a"
                 : tolerance ? "adaptive, mean " +
                                   FormatDouble(static_cast<double>(stats.samples) / texels) +
                                   ", max " + std::to_string(stats.maxTexelSamples)
                             : std::to_string(definition.SamplesPerTexel(s)));
  m.emplace_back("quadratureTexels", albedo ? std::to_string(stats.quadratureTexels) : "n/a");
  m.emplace_back("replicates", sampled ? std::to_string(replicates) : "n/a");
  m.emplace_back("seed", std::to_string(s.seed));
  // Every bound is stated for the value as stored (storage.h): the writers
  // add the rounding to their storage and say so in errorStorage.
  const std::string stored = "; plus the rounding of the stored value (see errorStorage)";
  char bound[320];
  std::snprintf(bound, sizeof bound,
                "sampled texels: %.3f standard errors (Student t, %d dof, two-sided 99%%) from the "
                "spread of %d independent %s, plus %s for events no sample met",
                StudentT99(replicates - 1), replicates - 1, replicates,
                random ? "random point sets" : "scrambles", definition.UnseenEventTerm().c_str());
  // Sampled texels that switch go to the default quadrature.
  BakeSettings quadrature = s;
  quadrature.estimator = Estimator::kQuadrature;
  std::string boundText;
  if (sampled)
    boundText = bound + (tolerance && s.allowQuadratureSwitch
                             ? "; " + definition.QuadratureBound(quadrature)
                             : std::string());
  else
    boundText = definition.QuadratureBound(s);
  m.emplace_back("errorBound", boundText + stored);
  for (auto &entry : definition.FitMetadata(table)) m.push_back(std::move(entry));
  m.emplace_back("lutbakeVersion", LutbakeVersion());
  m.emplace_back("commandLine", s.commandLine);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (statsOut) *statsOut = stats;
  return table;
}

}  // namespace lutbake
