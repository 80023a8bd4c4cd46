#include "microfacet_table.h"

#include <cmath>
#include <stdexcept>

#include "integrators/vndf_kernel.h"
#include "lutbake/integrators/albedo_estimator.h"
#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/reference_integrator.h"
#include "lutbake/tables/bake.h"
#include "sampled_texel.h"

namespace lutbake {

namespace {

class Microfacet final : public TableModel {
 public:
  std::vector<std::string> Options() const override { return {"ndf", "smith"}; }
  Metadata Records(const BakeSettings &s) const override {
    return {{"ndf", std::string(ToString(s.ndf))},
            {"smith", std::string(ToString(s.smith))},
            {"fresnel", "none (F = 1)"}};
  }
  std::string Alpha(const BakeSettings &) const override { return "alpha = perceptualRoughness^2"; }
  std::string Describe(const BakeSettings &s) const override {
    return std::string(ToString(s.ndf)) + " " + std::string(ToString(s.smith));
  }
  void Read(const Table &table, BakeSettings *s,
            std::vector<std::string> *problems) const override {
    const std::string ndf = RequiredMetadata(table, "ndf", problems),
                      smith = RequiredMetadata(table, "smith", problems);
    if (ndf != "ggx" && ndf != "beckmann") problems->push_back("ndf '" + ndf + "' unknown");
    if (smith != "correlated" && smith != "separable")
      problems->push_back("smith '" + smith + "' unknown");
    s->ndf = ndf == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
    s->smith = smith == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
    if (RequiredMetadata(table, "alpha", problems) != "alpha = perceptualRoughness^2")
      problems->push_back("alpha is not perceptualRoughness^2");
  }
  bool Same(const BakeSettings &a, const BakeSettings &b) const override {
    return a.ndf == b.ndf && a.smith == b.smith;
  }
};

}  // namespace

const TableModel &MicrofacetModel() {
  static const Microfacet model;
  return model;
}

bool MicrofacetTable::ReadModel(const Table &table, BakeSettings *s,
                                std::vector<std::string> *problems) const {
  const size_t before = problems->size();
  MicrofacetModel().Read(table, s, problems);
  // The roughness axis is the one a plan narrows; the other (of a 2D
  // table) is mu.
  const bool twoD = PlannedRoughnessAxis() == 1;
  const Axis &r = twoD ? table.y : table.x;
  if (r.name != "perceptualRoughness" || r.min < 0.0 || r.max > 1.0)
    problems->push_back("the roughness axis is not perceptualRoughness within [0, 1]");
  if (twoD && (table.x.name != "mu" || table.x.min < 0.0 || table.x.max > 1.0))
    problems->push_back("axis x is not mu within [0, 1]");
  if (!twoD && table.is2D()) problems->push_back(std::string(Name()) + " is not 1D");
  if (twoD && !table.is2D()) problems->push_back(table.Name() + " is not 2D");
  return problems->size() == before;
}

PointCoordinate MicrofacetTable::RoughnessCoordinate() {
  PointCoordinate c;
  c.option = "roughness";
  c.min = std::sqrt(kMinimumAlpha);
  c.max = 1.0;
  c.zeroAllowed = true;
  c.accepted = "comma-separated numbers: 0 (a mirror) or 1e-12 to 1";
  c.meaning = "perceptual roughness r (alpha = r^2; 0 is the mirror, exact)";
  return c;
}

PointCoordinate MicrofacetTable::MuCoordinate() {
  PointCoordinate c;
  c.option = "mu";
  c.accepted = "comma-separated numbers in [0, 1]";
  c.meaning = "view cosine mu = n.v (0: the grazing limit)";
  return c;
}

void MicrofacetTable::AddRoughnessNotes(HeaderText *text) {
  text->notes.push_back("Roughness is perceptual roughness r; the NDF width is alpha = r^2.");
  text->constants.push_back("inline constexpr bool kAlphaIsPerceptualRoughnessSquared = true;");
}

namespace {

using TexelResult = PointValue;

SampleStrategy StrategyOf(Estimator estimator) {
  switch (estimator) {
    case Estimator::kNdf: return SampleStrategy::kNdf;
    case Estimator::kCosine: return SampleStrategy::kCosine;
    case Estimator::kUniform: return SampleStrategy::kUniform;
    default: return SampleStrategy::kVisibleNormal;
  }
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

// GGX's visible-normal sampler has a SIMD kernel (vndf_kernel.h).
bool VectorisedVisibleNormals(const BakeSettings &s) {
  return s.ndf == NdfKind::kGgx && StrategyOf(s.estimator) == SampleStrategy::kVisibleNormal;
}

// The maximum of c (1 - c)^6 over [0, 1], at c = 1/7: 6^6 / 7^7.
constexpr double kF82MaxWeight = 46656.0 / 823543.0;

// The F82 weight (o.h) (1 - o.h)^6 at o.h = c in [0, 1].
double F82Weight(double c) {
  const double y = 1.0 - c, y2 = y * y;
  return c * (y2 * y2 * y2);
}

void CheckAlpha(double alpha) {
  // Written so that NaN fails too.
  if (!(alpha == 0.0 || (alpha >= kMinimumAlpha && alpha <= 1.0)))
    throw std::domain_error("alpha " + FormatDouble(alpha) + " is outside {0} and [" +
                            FormatDouble(kMinimumAlpha) + ", 1]");
}

}  // namespace

PointValue EvaluateAlbedo(const TableDefinition &table, const BakeSettings &s, double mu_o,
                          double alpha, uint64_t pointSeed) {
  CheckAlpha(alpha);
  if (!(mu_o >= 0.0 && mu_o <= 1.0))
    throw std::domain_error("mu " + FormatDouble(mu_o) + " is outside [0, 1]");
  const Ndf ndf{s.ndf, alpha};
  // Channels() builds the channel names: once per table and thread, not
  // per texel.
  thread_local const TableDefinition *channelsOf = nullptr;
  thread_local bool splitOf = false;
  if (channelsOf != &table) splitOf = table.Channels() == 2, channelsOf = &table;
  const bool split = splitOf;
  if (alpha == 0.0) return MirrorAlbedo(split, mu_o);
  if (s.estimator == Estimator::kQuadrature) return PanelAlbedo(split, s, ndf, mu_o);
  if (s.estimator == Estimator::kAdaptiveQuadrature) return AdaptiveAlbedo(split, s, ndf, mu_o);
  const AlbedoEstimator estimator{ndf, s.smith, StrategyOf(s.estimator)};
  const Vec3 o = ViewDirection(mu_o);
  const double L_o = ndf.MuLambda(mu_o);
  const uint64_t seed = SampleSeed(table.SeedId(), s, pointSeed);
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

// The F82 term C (table f82) at (mu_o, alpha): E's integrators with the
// weight (o.h) (1 - o.h)^6 in place of Schlick's. The sampled estimators are
// E's scalar ones (the GGX SIMD sampler computes A and B only). For visible
// normals the weight G2 / G1(o) (o.h) (1 - o.h)^6 lies in [0, 6^6 / 7^7]
// (G2 <= G1(o), and the maximum of c (1 - c)^6 is at c = 1/7), so the
// unseen-event term of the bound is 6^6 / 7^7 x 4.6 / N; the other
// estimators keep E's 4.6 / N.
PointValue EvaluateF82(const TableDefinition &table, const BakeSettings &s, double mu_o,
                       double alpha, uint64_t pointSeed) {
  CheckAlpha(alpha);
  if (!(mu_o >= 0.0 && mu_o <= 1.0))
    throw std::domain_error("mu " + FormatDouble(mu_o) + " is outside [0, 1]");
  const Ndf ndf{s.ndf, alpha};
  const auto panel = [&] {
    const F82Quadrature q = IntegrateF82Quadrature(ndf, s.smith, mu_o, PanelTolerance(s));
    TexelResult out;
    out.value[0] = q.C;
    out.error[0] = q.bound;
    out.evaluations = q.evaluations;
    out.quadrature = true;
    return out;
  };
  if (alpha == 0.0) {
    // The mirror: o.h = mu_o, G2 = 1, C = mu_o (1 - mu_o)^6, exact.
    TexelResult out;
    out.value[0] = F82Weight(mu_o);
    out.quadrature = out.exact = true;
    return out;
  }
  if (s.estimator == Estimator::kQuadrature) return panel();
  if (s.estimator == Estimator::kAdaptiveQuadrature) {
    const ReferenceF82 r = IntegrateReferenceF82(ndf, s.smith, mu_o, AdaptiveTolerance(s));
    TexelResult out;
    out.value[0] = r.C;
    out.error[0] = kQuadratureErrorFactor * r.error + kQuadratureErrorFloor;
    out.evaluations = static_cast<uint64_t>(r.evaluations);
    out.quadrature = true;
    return out;
  }
  const AlbedoEstimator estimator{ndf, s.smith, StrategyOf(s.estimator)};
  const Vec3 o = ViewDirection(mu_o);
  const double L_o = ndf.MuLambda(mu_o);
  TexelResult out;
  const bool sampled = SampleTexel<2, 1>(
      s,
      [&](const PointView &p, double *w[]) {
        for (size_t k = 0; k < p.n; ++k) {
          const AlbedoSample a = estimator.Sample(o, L_o, p.u[0][k], p.u[1][k]);
          w[0][k] = a.weight * F82Weight(a.cosThetaD);
        }
      },
      s.samples, SampleSeed(table.SeedId(), s, pointSeed), &out,
      StrategyOf(s.estimator) == SampleStrategy::kVisibleNormal ? kF82MaxWeight : 1.0);
  if (sampled) return out;
  TexelResult q = panel();
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
  const TableDefinition &average = TableNamed("Eavg");
  const uint64_t seed = SampleSeed(average.SeedId(), s, pointSeed);
  const uint64_t samples = average.SamplesPerTexel(s);
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

void MuRoughnessTable::Axes(const BakeSettings &, int size, Axis *x, Axis *y) const {
  *x = MuAxis(size);
  *y = RoughnessAxis(size);
}

}  // namespace lutbake
