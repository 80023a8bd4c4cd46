#include "lutbake/tables/bake.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "integrators/vndf_kernel.h"
#include "lutbake/core/hash.h"
#include "lutbake/integrators/albedo_estimator.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/integrators/replicated_integrator.h"

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
  }
}

uint64_t SamplesPerTexel(TableKind kind, const BakeSettings &settings) {
  if (kind == TableKind::kFavg || IsQuadrature(settings.estimator)) return 0;
  if (kind == TableKind::kEavg) return settings.samples * kAverageSampleFactor;
  return settings.samples;
}

namespace {

// The per-texel integral, whatever the estimator: returns the values and
// their error bounds for up to 2 channels, and what it cost.
using TexelResult = PointValue;

SampleStrategy StrategyOf(Estimator estimator) {
  switch (estimator) {
    case Estimator::kNdf: return SampleStrategy::kNdf;
    case Estimator::kCosine: return SampleStrategy::kCosine;
    case Estimator::kUniform: return SampleStrategy::kUniform;
    default: return SampleStrategy::kVisibleNormal;
  }
}

PointSet PointSetOf(Estimator estimator) {
  return estimator == Estimator::kVisibleNormal || estimator == Estimator::kNdf
             ? PointSet::kScrambledSobol
             : PointSet::kIndependentRandom;
}

double AdaptiveTolerance(const BakeSettings &s) {
  // A tolerance run asks the adaptive quadrature for EPS / 32: its reported
  // bound, 16 x the estimate plus the floor, then stays below EPS down to 1e-9.
  return s.tolerance > 0.0 ? s.tolerance / (2.0 * kQuadratureErrorFactor)
                           : kQuadratureDefaultTolerance;
}

// The bound the panel quadrature is asked for.
double PanelTolerance(const BakeSettings &s) {
  return s.tolerance > 0.0 ? s.tolerance : kDefaultQuadratureTolerance;
}

// A mirror (alpha = 0) is exact, not integrated: its only microfacet is n,
// so the light is the mirror direction, G2 = 1, and E = 1, B = (1 - mu)^5.
TexelResult MirrorAlbedo(bool split, double mu_o) {
  const SchlickWeights fc = Schlick(mu_o);
  TexelResult out;
  out.value[0] = split ? fc.complement : 1.0;
  out.value[1] = fc.fc;
  out.quadrature = true;
  out.exact = true;
  return out;
}

TexelResult PanelAlbedo(bool split, const BakeSettings &s, const Ndf &ndf, double mu_o) {
  const SplitSumQuadrature q =
      IntegrateSplitSumQuadrature(ndf, s.smith, mu_o, PanelTolerance(s), split);
  TexelResult out;
  out.value[0] = split ? q.A : q.A + q.B;
  out.value[1] = q.B;
  out.error[0] = split ? q.boundA : q.boundE;
  out.error[1] = q.boundB;
  out.evaluations = q.evaluations;
  out.quadrature = true;
  return out;
}

TexelResult PanelAverage(const BakeSettings &s, const Ndf &ndf) {
  const AverageQuadrature q = IntegrateAverageQuadrature(ndf, s.smith, PanelTolerance(s));
  TexelResult out;
  out.value[0] = q.value;
  out.error[0] = q.bound;
  out.evaluations = q.evaluations;
  out.quadrature = true;
  return out;
}

TexelResult AdaptiveAlbedo(bool split, const BakeSettings &s, const Ndf &ndf, double mu_o) {
  const ReferenceAlbedo r = IntegrateReferenceAlbedo(ndf, s.smith, mu_o, AdaptiveTolerance(s));
  TexelResult out;
  out.value[0] = split ? r.A : r.E;
  out.value[1] = r.B;
  // A mirror is exact (error 0); otherwise the estimate plus the floor.
  const double bound =
      ndf.alpha == 0.0 ? 0.0 : kQuadratureErrorFactor * r.error + kQuadratureErrorFloor;
  out.error[0] = out.error[1] = bound;
  out.evaluations = static_cast<uint64_t>(r.evaluations);
  out.quadrature = true;
  out.exact = ndf.alpha == 0.0;
  return out;
}

TexelResult AdaptiveAverage(const BakeSettings &s, const Ndf &ndf) {
  const double tolerance =
      s.tolerance > 0.0 ? AdaptiveTolerance(s) : 10.0 * kQuadratureDefaultTolerance;
  const ReferenceAverage r = IntegrateReferenceAlbedoAverage(ndf, s.smith, tolerance);
  TexelResult out;
  out.value[0] = r.value;
  out.error[0] = ndf.alpha == 0.0 ? 0.0 : kQuadratureErrorFactor * r.error + kQuadratureErrorFloor;
  out.evaluations = r.evaluations;
  out.quadrature = true;
  out.exact = ndf.alpha == 0.0;
  return out;
}

// Runs a sampled estimator on one texel: a fixed number of samples, or in
// rounds (doubling) until the bound is at most the tolerance. Returns false
// when a tolerance run decides that the quadrature is the cheaper way to
// EPS (the caller then integrates the texel with it).
template <int Dims, int Channels, typename BatchFn>
bool SampleTexel(const BakeSettings &s, const BatchFn &batch, uint64_t samples, uint64_t seed,
                 TexelResult *out) {
  const PointSet points = PointSetOf(s.estimator);
  const auto finish = [&](const ReplicatedAccumulator<Dims, Channels> &acc) {
    const ReplicatedEstimate<Channels> e = acc.Estimate();
    const double sigmas = StudentT99(acc.replicates() - 1);
    // The spread of the replicates cannot see an event rarer than about one
    // in N: GGX's tail past the horizon is such an event (probability up to
    // ~1e-4, weight 0 instead of ~1), and when no sample meets it every
    // replicate is off by the same amount. With weights in [0, 1], an event
    // that N samples all missed has, at 99% confidence, probability below
    // -ln(0.01) / N, and moves the integral by at most that much: the bound
    // adds it.
    const double unseen = kUnseenEventCount / static_cast<double>(acc.samples());
    for (int c = 0; c < Channels; ++c) {
      out->value[c] = e.mean[c];
      out->error[c] = sigmas * e.standardError[c] + unseen;
    }
    out->samples = acc.samples();
  };
  if (s.tolerance <= 0.0) {
    const int k =
        static_cast<int>(std::max<uint64_t>(1, std::min<uint64_t>(s.replicates, samples)));
    ReplicatedAccumulator<Dims, Channels> acc(k, seed, points);
    acc.ExtendTotalBatched(batch, samples);
    finish(acc);
    return true;
  }
  ReplicatedAccumulator<Dims, Channels> acc(s.replicates, seed, points);
  const uint64_t k = static_cast<uint64_t>(acc.replicates());
  // When the unseen-event term alone needs more samples than the quadrature
  // costs, no sampling round can pay off: go to the quadrature at once.
  const double minimumSamples = kUnseenEventCount / s.tolerance;
  if (s.allowQuadratureSwitch && minimumSamples > static_cast<double>(kQuadratureSwitchSamples))
    return false;
  uint64_t perReplicate = std::max<uint64_t>(2, samples / k);
  for (;;) {
    acc.ExtendBatched(batch, perReplicate);
    finish(acc);
    const double bound = *std::max_element(out->error, out->error + Channels);
    if (bound <= s.tolerance) return true;
    // Error ~ 1/N: the samples this texel would need.
    const double needed = static_cast<double>(acc.samples()) * bound / s.tolerance;
    if (s.allowQuadratureSwitch && needed > static_cast<double>(kQuadratureSwitchSamples))
      return false;
    if (2 * perReplicate * k > s.maxSamples) return true;  // caller sees bound > EPS
    perReplicate *= 2;
  }
}

// Scrambled Sobol points are shared by every texel of a table (their
// trigonometry is then computed once, point_blocks.h): seeded by the table
// and --seed. Independent random points keep the texel's own seed.
uint64_t SampleSeed(TableKind kind, const BakeSettings &s, uint64_t pointSeed) {
  return PointSetOf(s.estimator) == PointSet::kScrambledSobol
             ? HashValues({static_cast<uint64_t>(kind), s.seed, 0x736f626f6cULL})
             : pointSeed;
}

// GGX's visible-normal sampler has a SIMD kernel (vndf_kernel.h).
bool VectorisedVisibleNormals(const BakeSettings &s) {
  return s.ndf == NdfKind::kGgx && StrategyOf(s.estimator) == SampleStrategy::kVisibleNormal;
}

}  // namespace

uint64_t PointSeed(TableKind kind, double x, double y, uint64_t seed) {
  uint64_t xBits, yBits;
  std::memcpy(&xBits, &x, sizeof x);
  std::memcpy(&yBits, &y, sizeof y);
  return HashValues({static_cast<uint64_t>(kind), xBits, yBits, seed});
}

namespace {

void CheckAlpha(double alpha) {
  // Written so that NaN fails too.
  if (!(alpha == 0.0 || (alpha >= kMinimumAlpha && alpha <= 1.0)))
    throw std::domain_error("alpha " + FormatDouble(alpha) + " is outside {0} and [" +
                            FormatDouble(kMinimumAlpha) + ", 1]");
}

}  // namespace

PointValue EvaluateAlbedo(TableKind kind, const BakeSettings &s, double mu_o, double alpha,
                          uint64_t pointSeed) {
  CheckAlpha(alpha);
  if (!(mu_o >= 0.0 && mu_o <= 1.0))
    throw std::domain_error("mu " + FormatDouble(mu_o) + " is outside [0, 1]");
  const Ndf ndf{s.ndf, alpha};
  const bool split = kind == TableKind::kDfg;
  if (alpha == 0.0) return MirrorAlbedo(split, mu_o);
  if (s.estimator == Estimator::kQuadrature) return PanelAlbedo(split, s, ndf, mu_o);
  if (s.estimator == Estimator::kAdaptiveQuadrature) return AdaptiveAlbedo(split, s, ndf, mu_o);
  const AlbedoEstimator estimator{ndf, s.smith, StrategyOf(s.estimator)};
  const Vec3 o = ViewDirection(mu_o);
  const double L_o = ndf.MuLambda(mu_o);
  const uint64_t seed = SampleSeed(kind, s, pointSeed);
  TexelResult out;
  bool sampled;
  if (VectorisedVisibleNormals(s)) {
    // The SIMD kernel: the same weights as the estimator's, in batches.
    const auto weights = [&](const PointView &p, double *a, double *b) {
      kernel::GgxVisibleNormalWeights(alpha, s.smith, mu_o, L_o, p.n, p.cosPhi, p.sinPhi, p.u[1],
                                      nullptr, a, b);
    };
    sampled = split ? SampleTexel<2, 2>(
                          s, [&](const PointView &p, double *w[]) { weights(p, w[0], w[1]); },
                          s.samples, seed, &out)
                    : SampleTexel<2, 1>(
                          s, [&](const PointView &p, double *w[]) { weights(p, w[0], nullptr); },
                          s.samples, seed, &out);
  } else if (split) {
    sampled = SampleTexel<2, 2>(
        s,
        [&](const PointView &p, double *w[]) {
          for (size_t k = 0; k < p.n; ++k) {
            const AlbedoSample a = estimator.Sample(o, L_o, p.u[0][k], p.u[1][k]);
            w[0][k] = a.weight * a.schlickComplement;
            w[1][k] = a.weight * a.schlickWeight;
          }
        },
        s.samples, seed, &out);
  } else {
    sampled = SampleTexel<2, 1>(
        s,
        [&](const PointView &p, double *w[]) {
          for (size_t k = 0; k < p.n; ++k)
            w[0][k] = estimator.Sample(o, L_o, p.u[0][k], p.u[1][k]).weight;
        },
        s.samples, seed, &out);
  }
  if (sampled) return out;
  TexelResult q = PanelAlbedo(split, s, ndf, mu_o);
  q.samples = out.samples;  // the rounds spent before switching still count
  return q;
}

// E_avg(r) = 2 integral_0^1 E(mu) mu dmu as one 3D integral: mu = sqrt(u0)
// has density 2 mu, so the weight is the E estimator's at that mu.
PointValue EvaluateAlbedoAverage(const BakeSettings &s, double alpha, uint64_t pointSeed) {
  CheckAlpha(alpha);
  const Ndf ndf{s.ndf, alpha};
  if (alpha == 0.0) {
    TexelResult mirror;
    mirror.value[0] = 1.0;  // E = 1 at every mu
    mirror.quadrature = mirror.exact = true;
    return mirror;
  }
  if (s.estimator == Estimator::kQuadrature) return PanelAverage(s, ndf);
  if (s.estimator == Estimator::kAdaptiveQuadrature) return AdaptiveAverage(s, ndf);
  const AlbedoEstimator estimator{ndf, s.smith, StrategyOf(s.estimator)};
  const uint64_t seed = SampleSeed(TableKind::kEavg, s, pointSeed);
  const uint64_t samples = SamplesPerTexel(TableKind::kEavg, s);
  TexelResult out;
  bool sampled;
  if (VectorisedVisibleNormals(s)) {
    sampled = SampleTexel<3, 1>(
        s,
        [&](const PointView &p, double *w[]) {
          kernel::GgxVisibleNormalWeights(alpha, s.smith, 0.0, 0.0, p.n, p.cosPhi, p.sinPhi, p.u[2],
                                          p.u[0], w[0], nullptr);
        },
        samples, seed, &out);
  } else {
    sampled = SampleTexel<3, 1>(
        s,
        [&](const PointView &p, double *w[]) {
          for (size_t k = 0; k < p.n; ++k) {
            const double mu_o = std::sqrt(p.u[0][k]);
            const Vec3 o = ViewDirection(mu_o);
            w[0][k] = estimator.Sample(o, ndf.MuLambda(mu_o), p.u[1][k], p.u[2][k]).weight;
          }
        },
        samples, seed, &out);
  }
  if (sampled) return out;
  TexelResult q = PanelAverage(s, ndf);
  q.samples = out.samples;
  return q;
}

PointValue EvaluateFresnelAverage(FresnelModel model, double x, double y) {
  FresnelAverageResult r;
  switch (model) {
    case FresnelModel::kSchlick: r = SchlickFresnelAverage(x); break;
    case FresnelModel::kDielectric: r = ExactFresnelAverage(x, 0.0); break;
    case FresnelModel::kConductor: r = ExactFresnelAverage(x, y); break;
  }
  TexelResult out;
  out.value[0] = r.value;
  out.error[0] = r.error;
  out.quadrature = true;
  return out;
}

void DefaultAxes(TableKind kind, const BakeSettings &s, Axis *x, Axis *y) {
  switch (kind) {
    case TableKind::kE:
      *x = MuAxis(s.sizeE);
      *y = RoughnessAxis(s.sizeE);
      break;
    case TableKind::kDfg:
      *x = MuAxis(s.sizeDfg);
      *y = RoughnessAxis(s.sizeDfg);
      break;
    case TableKind::kEavg:
      *x = RoughnessAxis(s.sizeEavg);
      *y = LinearAxis("", 0.0, 1.0, 1);
      break;
    case TableKind::kFavg: FresnelAxes(s.fresnel, s.sizeFavg, x, y); break;
  }
}

Table BakeTable(TableKind kind, const BakeSettings &s, const ProgressFn &progress,
                BakeStats *statsOut) {
  Axis x, y;
  DefaultAxes(kind, s, &x, &y);
  return BakeTableOn(kind, s, x, y, progress, statsOut);
}

Table BakeTableOn(TableKind kind, const BakeSettings &s, const Axis &x, const Axis &y,
                  const ProgressFn &progress, BakeStats *statsOut) {
  const auto start = std::chrono::steady_clock::now();
  Table table;
  table.kind = kind;
  table.x = x;
  table.y = y;
  table.channels = kind == TableKind::kDfg ? 2 : 1;
  table.channelNames =
      kind == TableKind::kDfg ? std::vector<std::string>{"R", "G"} : std::vector<std::string>{"Y"};
  const size_t texels = static_cast<size_t>(table.width()) * table.height();
  table.values.assign(texels * table.channels, 0.0);
  table.errors.assign(texels * table.channels, 0.0);

  std::vector<uint64_t> texelSamples(texels, 0), texelEvaluations(texels, 0);
  std::vector<uint8_t> texelQuadrature(texels, 0);
  std::atomic<size_t> done{0};
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, texels), [&](const tbb::blocked_range<size_t> &r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          // Column by column (k runs down each column of constant mu): the
          // quadrature's azimuthal nodes depend on mu only, and a thread
          // that stays in a column reuses them. Each texel is computed
          // alone, so the order changes nothing in the values.
          const int ix = static_cast<int>(k / table.height());
          const int iy = static_cast<int>(k % table.height());
          const size_t t = static_cast<size_t>(iy) * table.width() + ix;
          TexelResult texel;
          switch (kind) {
            case TableKind::kE:
            case TableKind::kDfg: {
              const double mu = table.x.TexelCenter(ix), r_ = table.y.TexelCenter(iy);
              const double alpha = r_ * r_;
              texel = EvaluateAlbedo(kind, s, mu, alpha, PointSeed(kind, mu, alpha, s.seed));
              break;
            }
            case TableKind::kEavg: {
              const double r_ = table.x.TexelCenter(ix);
              const double alpha = r_ * r_;
              texel = EvaluateAlbedoAverage(s, alpha, PointSeed(kind, alpha, 0.0, s.seed));
              break;
            }
            case TableKind::kFavg:
              texel = EvaluateFresnelAverage(s.fresnel, table.x.TexelCenter(ix),
                                             table.y.TexelCenter(iy));
              break;
          }
          for (int c = 0; c < table.channels; ++c) {
            table.values[t * table.channels + c] = texel.value[c];
            table.errors[t * table.channels + c] = texel.error[c];
          }
          texelSamples[t] = texel.samples;
          texelEvaluations[t] = texel.evaluations;
          texelQuadrature[t] = texel.quadrature ? 1 : 0;
        }
        const size_t now = done.fetch_add(r.size()) + r.size();
        if (progress) progress(static_cast<double>(now) / static_cast<double>(texels));
      });

  BakeStats stats;
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

  const bool albedo = kind != TableKind::kFavg;
  const bool sampled = albedo && !IsQuadrature(s.estimator);
  const bool tolerance = sampled && s.tolerance > 0.0;
  const int replicates = tolerance
                             ? std::clamp(s.replicates, 1, 64)
                             : static_cast<int>(std::min<uint64_t>(
                                   s.replicates, std::max<uint64_t>(1, SamplesPerTexel(kind, s))));
  const bool random = PointSetOf(s.estimator) == PointSet::kIndependentRandom;
  auto &m = table.metadata;
  m.emplace_back("table", TableName(kind));
  m.emplace_back("ndf", albedo ? std::string(ToString(s.ndf)) : "none");
  m.emplace_back("smith", albedo ? std::string(ToString(s.smith)) : "none");
  m.emplace_back("fresnel", albedo ? "none (F = 1)" : std::string(ToString(s.fresnel)));
  m.emplace_back("axisX", DescribeAxis(table.x));
  m.emplace_back("axisY", table.is2D() ? DescribeAxis(table.y) : "none (1D table)");
  m.emplace_back("alpha", albedo ? "alpha = perceptualRoughness^2" : "n/a");
  std::string convention =
      "texel i of N holds the value at u = (i + 0.5) / N, mapped linearly onto [min, max]; "
      "y = 0 first";
  if (table.x.listed() || table.y.listed())
    convention +=
        "; an axis described as 'values [...]' holds texel i at exactly its i-th value, and "
        "lookups interpolate linearly in that value between neighbouring texels";
  m.emplace_back("texelConvention", convention);
  m.emplace_back("channelLayout", kind == TableKind::kDfg ? "R = A (scale), G = B (bias)"
                                                          : "Y = " + std::string(TableName(kind)));
  std::string estimatorText =
      s.estimator == Estimator::kAdaptiveQuadrature
          ? "adaptive Gauss-Kronrod quadrature"
          : "panel Gauss-Legendre quadrature over the half vector, two orders";
  if (sampled)
    estimatorText =
        std::string(ToString(s.estimator)) +
        (random ? " with independent random points" : " with Owen-scrambled Sobol points");
  if (tolerance && s.allowQuadratureSwitch)
    estimatorText += "; texels for which the quadrature is cheaper switch to it";
  m.emplace_back("estimator", estimatorText);
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
                             : std::to_string(SamplesPerTexel(kind, s)));
  m.emplace_back("quadratureTexels", albedo ? std::to_string(stats.quadratureTexels) : "n/a");
  m.emplace_back("replicates", sampled ? std::to_string(replicates) : "n/a");
  m.emplace_back("seed", std::to_string(s.seed));
  // Every bound is stated for the value as stored (storage.h): the writers
  // add the rounding to their storage and say so in errorStorage.
  const std::string panel =
      "quadrature texels: |V_k - V_(k-1)| + 1e-10 of the panel rule at two orders";
  const std::string stored = "; plus the rounding of the stored value (see errorStorage)";
  char bound[320];
  std::snprintf(bound, sizeof bound,
                "sampled texels: %.3f standard errors (Student t, %d dof, two-sided 99%%) from the "
                "spread of %d independent %s, plus 4.6 / N for events no sample met",
                StudentT99(replicates - 1), replicates - 1, replicates,
                random ? "random point sets" : "scrambles");
  std::string boundText;
  if (!albedo)
    boundText = "Gauss-Kronrod error estimate";
  else if (s.estimator == Estimator::kAdaptiveQuadrature)
    boundText = FormatDouble(kQuadratureErrorFactor) + " x the Gauss-Kronrod estimate + 1e-10";
  else if (sampled)
    boundText = bound + (tolerance && s.allowQuadratureSwitch ? "; " + panel : std::string());
  else
    boundText = panel;
  m.emplace_back("errorBound", boundText + stored);
  m.emplace_back("lutbakeVersion", LutbakeVersion());
  m.emplace_back("commandLine", s.commandLine);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (statsOut) *statsOut = stats;
  return table;
}

}  // namespace lutbake
