#include "lutbake/bake.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdio>

#include "lutbake/albedo_estimator.h"
#include "lutbake/reference_integrator.h"
#include "lutbake/replicated_integrator.h"

#ifndef LUTBAKE_VERSION
#define LUTBAKE_VERSION "unknown"
#endif

namespace lutbake {

const char *LutbakeVersion() { return LUTBAKE_VERSION; }

std::string_view ToString(Estimator estimator) {
  switch (estimator) {
    case Estimator::kVisibleNormal: return "vndf";
    case Estimator::kNdf: return "ndf";
    case Estimator::kQuadrature: return "quadrature";
  }
  return "?";
}

Axis MuAxis(int count) { return {"mu", 0.0, 1.0, count}; }
Axis RoughnessAxis(int count) { return {"perceptualRoughness", 0.0, 1.0, count}; }

void FresnelAxes(FresnelModel model, int count, Axis *x, Axis *y) {
  *y = Axis{"", 0.0, 1.0, 1};
  switch (model) {
    case FresnelModel::kSchlick: *x = {"F0", 0.0, 1.0, count}; break;
    // Relative IOR from 1 (no interface) to 3: every common dielectric,
    // diamond (2.42) included, lies inside.
    case FresnelModel::kDielectric: *x = {"eta", 1.0, 3.0, count}; break;
    // Complex IOR eta + i k: metals across the visible spectrum have
    // eta in (0, 4) and k in (0, 10) (gold, copper, aluminium, iron, ...).
    case FresnelModel::kConductor:
      *x = {"eta", 0.0, 4.0, count};
      *y = {"k", 0.0, 10.0, count};
      break;
  }
}

uint64_t SamplesPerTexel(TableKind kind, const BakeSettings &settings) {
  if (kind == TableKind::kEavg) return settings.samples * kAverageSampleFactor;
  return settings.samples;
}

namespace {

std::string FormatDouble(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string DescribeAxis(const Axis &axis) {
  return axis.name + " linear [" + FormatDouble(axis.min) + ", " + FormatDouble(axis.max) + "], " +
         std::to_string(axis.count) + " texels";
}

// The per-texel integral, whatever the estimator: returns the values and
// their error bounds for `channels` channels.
struct TexelResult {
  double value[2] = {0, 0};
  double error[2] = {0, 0};
};

AlbedoEstimator MakeEstimator(const BakeSettings &s, const Ndf &ndf) {
  return {ndf, s.smith,
          s.estimator == Estimator::kNdf ? SampleStrategy::kNdf : SampleStrategy::kVisibleNormal};
}

uint64_t TexelSeed(TableKind kind, size_t texel, uint64_t seed) {
  return HashValues({static_cast<uint64_t>(kind), texel, seed});
}

TexelResult AlbedoTexel(TableKind kind, const BakeSettings &s, double mu_o, double alpha,
                        size_t texel) {
  const Ndf ndf{s.ndf, alpha};
  TexelResult out;
  const bool split = kind == TableKind::kDfg;
  // A mirror (alpha = 0) is exact, not sampled: its only microfacet is n, so
  // the light is the mirror direction, G2 = 1, and E = 1, B = (1 - mu)^5.
  if (alpha == 0.0 || s.estimator == Estimator::kQuadrature) {
    const ReferenceAlbedo r = IntegrateReferenceAlbedo(ndf, s.smith, mu_o);
    out.value[0] = split ? r.A : r.E;
    out.value[1] = r.B;
    out.error[0] = out.error[1] = r.error;
    return out;
  }
  const AlbedoEstimator estimator = MakeEstimator(s, ndf);
  const Vec3 o = ViewDirection(mu_o);
  const double L_o = ndf.MuLambda(mu_o);
  const uint64_t seed = TexelSeed(kind, texel, s.seed);
  if (split) {
    const auto e = IntegrateReplicated<2, 2>(
        [&](const double(&u)[2]) {
          const AlbedoSample a = estimator.Sample(o, L_o, u[0], u[1]);
          return std::array<double, 2>{a.weight * (1.0 - a.schlickWeight),
                                       a.weight * a.schlickWeight};
        },
        s.samples, s.replicates, seed);
    for (int c = 0; c < 2; ++c) {
      out.value[c] = e.mean[c];
      out.error[c] = kErrorSigmas * e.standardError[c];
    }
  } else {
    const auto e = IntegrateReplicated<2, 1>(
        [&](const double(&u)[2]) {
          return std::array<double, 1>{estimator.Sample(o, L_o, u[0], u[1]).weight};
        },
        s.samples, s.replicates, seed);
    out.value[0] = e.mean[0];
    out.error[0] = kErrorSigmas * e.standardError[0];
  }
  return out;
}

// E_avg(r) = 2 integral_0^1 E(mu) mu dmu as one 3D integral: mu = sqrt(u0)
// has density 2 mu, so the weight is the E estimator's at that mu.
TexelResult AverageTexel(const BakeSettings &s, double alpha, size_t texel) {
  const Ndf ndf{s.ndf, alpha};
  TexelResult out;
  if (alpha == 0.0 || s.estimator == Estimator::kQuadrature) {
    const ReferenceAverage r = IntegrateReferenceAlbedoAverage(ndf, s.smith);
    out.value[0] = r.value;
    out.error[0] = r.error;
    return out;
  }
  const AlbedoEstimator estimator = MakeEstimator(s, ndf);
  const auto e = IntegrateReplicated<3, 1>(
      [&](const double(&u)[3]) {
        const double mu_o = std::sqrt(u[0]);
        const Vec3 o = ViewDirection(mu_o);
        return std::array<double, 1>{estimator.Sample(o, ndf.MuLambda(mu_o), u[1], u[2]).weight};
      },
      SamplesPerTexel(TableKind::kEavg, s), s.replicates,
      TexelSeed(TableKind::kEavg, texel, s.seed));
  out.value[0] = e.mean[0];
  out.error[0] = kErrorSigmas * e.standardError[0];
  return out;
}

TexelResult FresnelTexel(FresnelModel model, double x, double y) {
  FresnelAverageResult r;
  switch (model) {
    case FresnelModel::kSchlick: r = SchlickFresnelAverage(x); break;
    case FresnelModel::kDielectric: r = ExactFresnelAverage(x, 0.0); break;
    case FresnelModel::kConductor: r = ExactFresnelAverage(x, y); break;
  }
  TexelResult out;
  out.value[0] = r.value;
  out.error[0] = r.error;
  return out;
}

}  // namespace

Table BakeTable(TableKind kind, const BakeSettings &s, const ProgressFn &progress) {
  Table table;
  table.kind = kind;
  switch (kind) {
    case TableKind::kE:
      table.x = MuAxis(s.sizeE);
      table.y = RoughnessAxis(s.sizeE);
      break;
    case TableKind::kDfg:
      table.x = MuAxis(s.sizeDfg);
      table.y = RoughnessAxis(s.sizeDfg);
      break;
    case TableKind::kEavg:
      table.x = RoughnessAxis(s.sizeEavg);
      table.y = Axis{"", 0.0, 1.0, 1};
      break;
    case TableKind::kFavg: FresnelAxes(s.fresnel, s.sizeFavg, &table.x, &table.y); break;
  }
  table.channels = kind == TableKind::kDfg ? 2 : 1;
  table.channelNames =
      kind == TableKind::kDfg ? std::vector<std::string>{"R", "G"} : std::vector<std::string>{"Y"};
  const size_t texels = static_cast<size_t>(table.width()) * table.height();
  table.values.assign(texels * table.channels, 0.0);
  table.errors.assign(texels * table.channels, 0.0);

  std::atomic<size_t> done{0};
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, texels), [&](const tbb::blocked_range<size_t> &r) {
        for (size_t t = r.begin(); t != r.end(); ++t) {
          const int ix = static_cast<int>(t % table.width());
          const int iy = static_cast<int>(t / table.width());
          TexelResult texel;
          switch (kind) {
            case TableKind::kE:
            case TableKind::kDfg: {
              const double r_ = table.y.TexelCenter(iy);
              texel = AlbedoTexel(kind, s, table.x.TexelCenter(ix), r_ * r_, t);
              break;
            }
            case TableKind::kEavg: {
              const double r_ = table.x.TexelCenter(ix);
              texel = AverageTexel(s, r_ * r_, t);
              break;
            }
            case TableKind::kFavg:
              texel = FresnelTexel(s.fresnel, table.x.TexelCenter(ix), table.y.TexelCenter(iy));
              break;
          }
          for (int c = 0; c < table.channels; ++c) {
            table.values[t * table.channels + c] = texel.value[c];
            table.errors[t * table.channels + c] = texel.error[c];
          }
        }
        const size_t now = done.fetch_add(r.size()) + r.size();
        if (progress) progress(static_cast<double>(now) / static_cast<double>(texels));
      });

  const bool albedo = kind != TableKind::kFavg;
  const bool sampled = albedo && s.estimator != Estimator::kQuadrature;
  auto &m = table.metadata;
  m.emplace_back("table", TableName(kind));
  m.emplace_back("ndf", albedo ? std::string(ToString(s.ndf)) : "none");
  m.emplace_back("smith", albedo ? std::string(ToString(s.smith)) : "none");
  m.emplace_back("fresnel", albedo ? "none (F = 1)" : std::string(ToString(s.fresnel)));
  m.emplace_back("axisX", DescribeAxis(table.x));
  m.emplace_back("axisY", table.is2D() ? DescribeAxis(table.y) : "none (1D table)");
  m.emplace_back("alpha", albedo ? "alpha = perceptualRoughness^2" : "n/a");
  m.emplace_back("texelConvention",
                 "texel i of N holds the value at u = (i + 0.5) / N, "
                 "mapped linearly onto [min, max]; y = 0 first");
  m.emplace_back("channelLayout", kind == TableKind::kDfg ? "R = A (scale), G = B (bias)"
                                                          : "Y = " + std::string(TableName(kind)));
  m.emplace_back("estimator",
                 sampled ? std::string(ToString(s.estimator)) + " with Owen-scrambled Sobol points"
                         : "adaptive Gauss-Kronrod quadrature");
  m.emplace_back("samplesPerTexel", sampled ? std::to_string(SamplesPerTexel(kind, s)) : "n/a");
  m.emplace_back(
      "replicates",
      sampled ? std::to_string(std::min<uint64_t>(s.replicates, SamplesPerTexel(kind, s))) : "n/a");
  m.emplace_back("seed", std::to_string(s.seed));
  m.emplace_back("errorBound",
                 sampled ? "5.841 standard errors (Student t, 3 dof, 99%) from the spread of "
                           "4 independent scrambles"
                         : "quadrature error bound");
  m.emplace_back("errorMax", FormatDouble(table.MaxError()));
  m.emplace_back("errorRms", FormatDouble(table.RmsError()));
  m.emplace_back("lutbakeVersion", LutbakeVersion());
  m.emplace_back("commandLine", s.commandLine);
  return table;
}

}  // namespace lutbake
