// Table ltc_ggx: linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt
// 2016; models/ltc.h) fitted to the cosine-weighted microfacet lobe
// f(v, l) (n.l) of table E (F = 1, --ndf, --smith), for rectangular and
// polygonal area lights. Axes as E's: x = mu in [0, 1], y = perceptual
// roughness r (alpha = r^2), texel centres, 64 x 64 by default.
//
// Channels, in this order (issue 28):
//   m00, m20, m02, m22  M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
//                       (normalised so that its middle element is 1), acting
//                       on directions in the frame where n = +z and the view
//                       is v = (sqrt(1 - mu^2), 0, mu); det M^-1 > 0.
//   magnitude           int f (n.l) dl: exactly table E's value at the point
//                       (the same integrator, the same bound);
//   fresnel             int f (n.l) (1 - v.h)^5 dl: table dfg's B;
// so that the lobe is approximated by magnitude D(l), D the LTC density, and a
// Schlick F by F0 magnitude + (1 - F0) fresnel.
//
// The fit (integrators/ltc_fit.h) minimises the L1 error on the sphere by a
// deterministic quadrature, each texel started from its neighbour's along a
// path that keeps neighbours on one branch (FitLtcGrid); `lutbake eval` at a
// point walks the same path through the default grid (FitLtcPoint), so that
// at a texel centre it gives the bake's texel bit for bit. The matrix is the
// fit itself (its bound 0: what it is worth is the lobe error); magnitude
// and fresnel carry the quadrature's bounds. Beside the values every texel
// states (T.fit.exr, and summarised in the metadata) its lobe error
// int_{l.z>0} |f (n.l) - magnitude D| dl / magnitude, its worst relative
// error of the irradiance from LtcTestRectangles (clipped at the horizon),
// and its leakage int_{l.z<0} D dl, each measured for the matrix as stored
// in float32.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "definitions.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/bake.h"
#include "microfacet_table.h"

namespace lutbake {

namespace {

class LtcGgx final : public MuRoughnessTable {
 public:
  PlanRole Role() const override { return PlanRole::kAreaLights; }
  const char *Name() const override { return "ltc_ggx"; }
  uint64_t SeedId() const override { return 14; }
  std::string Summary() const override {
    return "linearly transformed cosine of the microfacet lobe (F = 1) for area lights: M^-1, "
           "magnitude = E, fresnel";
  }
  std::vector<std::string> ChannelNames() const override {
    return {"m00", "m20", "m02", "m22", "magnitude", "fresnel"};
  }
  std::vector<std::string> ChannelMeanings() const override { return ChannelNames(); }
  std::string ChannelLayout() const override {
    return "m00, m20, m02, m22 = M^-1 [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the frame n = "
           "+z, v = (sqrt(1 - mu^2), 0, mu); magnitude = int f (n.l) dl (= E); fresnel = int f "
           "(n.l) (1 - v.h)^5 dl";
  }
  int DefaultSize() const override { return 64; }
  bool Sampled() const override { return false; }
  std::string EstimatorProblem(Estimator e) const override {
    return e == Estimator::kQuadrature ? ""
                                       : "ltc_ggx is fitted by its deterministic quadrature only";
  }
  std::string QuadratureDescription(const BakeSettings &) const override {
    return "m00..m22: fitted by Nelder-Mead to the L1 error on the sphere, integrated by a "
           "half-vector quadrature, each texel started from its neighbour's (largest roughness "
           "first, from mu = 1 down, then each mu from the largest roughness down); magnitude "
           "and fresnel: table E's and dfg's panel Gauss-Legendre quadrature";
  }
  std::string QuadratureBound(const BakeSettings &) const override {
    return "m00..m22: 0 (the fit is the value; its quality is fitErrors); magnitude, fresnel: "
           "|V_k - V_(k-1)| + 1e-10 of the panel rule at two orders";
  }
  TableRelations Relations() const override {
    TableRelations r;
    r.channelIs = "E";
    r.channelIsChannel = 4;
    return r;
  }
  ValueClaim Range(const BakeSettings &) const override {
    return {-HUGE_VAL, HUGE_VAL, false, "finite"};
  }

  // The lobe at perceptual roughness r.
  static LtcLobe LobeAt(const BakeSettings &s, double r) {
    return MicrofacetLtcLobe(Ndf{s.ndf, r * r}, s.smith);
  }
  static LtcFitSettings FitSettings() {
    LtcFitSettings f;
    f.moments = false;  // E's and dfg's quadrature below
    return f;
  }
  // magnitude and fresnel (with their bounds) into channels 4 and 5.
  // The panel quadrature, as tables E and dfg bake; the adaptive one when
  // asked (check's reference).
  static void Moments(const BakeSettings &s, double mu, double r, PointValue *out) {
    BakeSettings q = s;
    if (q.estimator != Estimator::kAdaptiveQuadrature) q.estimator = Estimator::kQuadrature;
    const double alpha = r * r;
    const PointValue e = EvaluateAlbedo(DirectionalAlbedoTable(), q, mu, alpha, 0);
    const PointValue ab = EvaluateAlbedo(SplitSumTable(), q, mu, alpha, 0);
    out->value[4] = e.value[0];
    out->error[4] = e.error[0];
    out->value[5] = ab.value[1];
    out->error[5] = ab.error[1];
    out->evaluations += e.evaluations + ab.evaluations;
    out->quadrature = true;
  }
  static void Store(const LtcMatrix &m, PointValue *out) {
    out->value[0] = m.m00;
    out->value[1] = m.m20;
    out->value[2] = m.m02;
    out->value[3] = m.m22;
  }
  // The matrix as a float32 file stores it.
  static LtcMatrix Stored(const PointValue &v) {
    const auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
    return {f(v.value[0]), f(v.value[1]), f(v.value[2]), f(v.value[3])};
  }
  static std::vector<double> Centres(const Axis &a) {
    std::vector<double> out;
    for (int i = 0; i < a.count; ++i) out.push_back(a.TexelCenter(i));
    return out;
  }

  static void CheckPoint(double mu, double r) {
    if (!(mu >= 0.0 && mu <= 1.0) || !(r == 0.0 || (r >= std::sqrt(kMinimumAlpha) && r <= 1.0)))
      throw std::domain_error("(mu, r) = (" + FormatDouble(mu) + ", " + FormatDouble(r) +
                              ") is outside [0, 1] x ({0} or [1e-12, 1])");
  }
  PointValue Evaluate(const BakeSettings &s, double mu, double r) const override {
    CheckPoint(mu, r);
    Axis x, y;
    DefaultAxes(*this, s, &x, &y);
    const LtcTexel fit = FitLtcPoint([&s](double rr) { return LobeAt(s, rr); }, mu, r, Centres(x),
                                     Centres(y), FitSettings());
    PointValue out;
    Store(fit.minv, &out);
    Moments(s, mu, r, &out);
    out.evaluations += static_cast<uint64_t>(fit.evaluations);
    return out;
  }

  // The lobe error, polygon error and leakage of a texel as stored.
  static LtcErrors Errors(const BakeSettings &s, double mu, double r, const PointValue &v) {
    const LtcLobe lobe = LobeAt(s, r);
    const double magnitude = static_cast<float>(v.value[4]);
    return MeasureLtcErrors(lobe, mu, magnitude, Stored(v), RectangleLobeIntegrals(lobe, mu, 0));
  }

  bool BakedWhole() const override { return true; }
  std::vector<std::string> FitMapNames() const override {
    return {"lobeError", "polygonError", "leakage"};
  }
  uint64_t BakeWhole(const BakeSettings &s, Table *table) const override {
    const std::vector<double> mu = Centres(table->x), r = Centres(table->y);
    const std::vector<LtcTexel> fits =
        FitLtcGrid([&s](double rr) { return LobeAt(s, rr); }, mu, r, FitSettings());
    const int w = table->width(), h = table->height(), c = table->channels;
    table->fitMapNames = FitMapNames();
    table->fitMaps.assign(static_cast<size_t>(w) * h * 3, 0.0);
    std::vector<uint64_t> evaluations(static_cast<size_t>(w) * h, 0);
    tbb::parallel_for(0, w * h, [&](int t) {
      if (s.cancellation) s.cancellation->ThrowIfCancelled();
      const int ix = t % w, iy = t / w;  // mu, r
      const LtcTexel &fit = fits[static_cast<size_t>(ix) * h + iy];
      PointValue v;
      Store(fit.minv, &v);
      Moments(s, mu[ix], r[iy], &v);
      for (int k = 0; k < c; ++k) {
        table->values[static_cast<size_t>(t) * c + k] = v.value[k];
        table->errors[static_cast<size_t>(t) * c + k] = v.error[k];
      }
      const LtcErrors e = Errors(s, mu[ix], r[iy], v);
      table->fitMaps[static_cast<size_t>(t) * 3 + 0] = e.lobe;
      table->fitMaps[static_cast<size_t>(t) * 3 + 1] = e.polygon;
      table->fitMaps[static_cast<size_t>(t) * 3 + 2] = e.leakage;
      evaluations[t] = v.evaluations + static_cast<uint64_t>(fit.evaluations);
    });
    uint64_t sum = 0;
    for (uint64_t e : evaluations) sum += e;
    return sum;
  }
  std::vector<std::pair<std::string, double>> PointFitErrors(const BakeSettings &s, double mu,
                                                             double r,
                                                             const PointValue &v) const override {
    const LtcErrors e = Errors(s, mu, r, v);
    return {{"lobeError", e.lobe}, {"polygonError", e.polygon}, {"leakage", e.leakage}};
  }
  int FittedChannels() const override { return 4; }
  std::vector<double> FitParameters(const double *v) const override {
    const std::array<double, 4> p = LtcParameters({v[0], v[1], v[2], v[3]});
    return {p[0], p[1], p[2], p[3]};
  }
  std::string TexelProblem(const double *v) const override {
    const LtcMatrix m{v[0], v[1], v[2], v[3]};
    if (m.Determinant() > 0.0) return "";
    return "det M^-1 = " + FormatDouble(m.Determinant()) + " <= 0 (the light renders black)";
  }
  PointValue EvaluateIntegrals(const BakeSettings &s, double mu, double r) const override {
    CheckPoint(mu, r);
    PointValue out;
    for (int c = 0; c < 4; ++c) out.value[c] = NAN;
    Moments(s, mu, r, &out);
    return out;
  }
  Metadata FitMetadata(const Table &table) const override {
    const size_t n = table.fitMapNames.size();
    if (n == 0) return {};
    std::string text;
    for (size_t k = 0; k < n; ++k) {
      double mean = 0.0, worst = 0.0;
      const size_t texels = table.fitMaps.size() / n;
      for (size_t t = 0; t < texels; ++t) {
        mean += table.fitMaps[t * n + k];
        worst = std::max(worst, table.fitMaps[t * n + k]);
      }
      mean /= static_cast<double>(texels);
      char line[160];
      std::snprintf(line, sizeof line, "%s%s mean %.6g max %.6g", k ? "; " : "",
                    table.fitMapNames[k].c_str(), mean, worst);
      text += line;
    }
    return {{"fitErrors", text},
            {"fitErrorsMeaning",
             "per texel (T.fit.exr), for the values as stored: lobeError = int_{l.z>0} |f (n.l) - "
             "magnitude D| dl / magnitude (half-vector rule, within ~1.3e-3 at grazing views); "
             "polygonError = max over 12 test rectangles receiving >= 2% of the lobe (clipped at "
             "the horizon) of |magnitude int_P D - int_P f (n.l)| / int_P f (n.l); leakage = "
             "int_{l.z<0} D dl (closed form)"}};
  }

  HeaderText Header(const Table &) const override {
    HeaderText text;
    AddRoughnessNotes(&text);
    text.notes.push_back(
        "Linearly transformed cosines: M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the");
    text.notes.push_back(
        "frame n = +z, v = (sqrt(1 - mu^2), 0, mu); the lobe f (n.l) ~ magnitude D(l), a");
    text.notes.push_back("Schlick F gives F0 magnitude + (1 - F0) fresnel.");
    text.layout =
        "; channels m00, m20, m02, m22,\n"
        "// magnitude (= E), fresnel.\n";
    text.lookupComment =
        "{m00, m20, m02, m22, magnitude, fresnel} at view cosine mu and perceptual roughness r.";
    return text;
  }
};

}  // namespace

const TableDefinition &LtcGgxTable() {
  static const LtcGgx table;
  return table;
}

}  // namespace lutbake
