#include "ltc_table.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>

#include "lutbake/tables/bake.h"
#include "lutbake/tables/fitted_lobe.h"
#include "sampled_texel.h"

namespace lutbake {

namespace {

void Store(const LtcMatrix &m, PointValue *out) {
  out->value[0] = m.m00;
  out->value[1] = m.m20;
  out->value[2] = m.m02;
  out->value[3] = m.m22;
}

// The matrix as a float32 file stores it.
LtcMatrix Stored(const PointValue &v) {
  const auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
  return {f(v.value[0]), f(v.value[1]), f(v.value[2]), f(v.value[3])};
}

std::vector<double> Centres(const Axis &a) {
  std::vector<double> out;
  for (int i = 0; i < a.count; ++i) out.push_back(a.TexelCenter(i));
  return out;
}

}  // namespace

PointValue LtcEvaluate(const TableDefinition &def, const LtcLobeFamily &lobes,
                       const LtcFitSettings &fit, const BakeSettings &s, double mu, double y) {
  Axis xAxis, yAxis;
  DefaultAxes(def, s, &xAxis, &yAxis);
  const LtcTexel texel = FitLtcPoint([&](double yy) { return lobes.LobeAt(s, yy); }, mu, y,
                                     Centres(xAxis), Centres(yAxis), fit);
  PointValue out;
  Store(texel.minv, &out);
  lobes.Moments(s, mu, y, &out);
  out.evaluations += static_cast<uint64_t>(texel.evaluations);
  return out;
}

PointValue LtcEvaluateIntegrals(const LtcLobeFamily &lobes, const BakeSettings &s, double mu,
                                double y) {
  PointValue out;
  for (int c = 0; c < 4; ++c) out.value[c] = NAN;
  lobes.Moments(s, mu, y, &out);
  return out;
}

LtcErrors LtcPointErrors(const LtcLobeFamily &lobes, const BakeSettings &s, double mu, double y,
                         const PointValue &v) {
  const LtcLobe lobe = lobes.LobeAt(s, y);
  const double magnitude = static_cast<float>(v.value[4]);
  return MeasureLtcErrors(lobe, mu, magnitude, Stored(v), RectangleLobeIntegrals(lobe, mu, 0));
}

uint64_t LtcBakeWhole(const LtcLobeFamily &lobes, const LtcFitSettings &fit,
                      const std::vector<std::string> &mapNames, const BakeSettings &s,
                      Table *table) {
  const std::vector<double> mu = Centres(table->x), ys = Centres(table->y);
  const std::vector<LtcTexel> fits =
      FitLtcGrid([&](double y) { return lobes.LobeAt(s, y); }, mu, ys, fit);
  const int w = table->width(), h = table->height(), c = table->channels;
  table->fitMapNames = mapNames;
  table->fitMaps.assign(static_cast<size_t>(w) * h * 3, 0.0);
  std::vector<uint64_t> evaluations(static_cast<size_t>(w) * h, 0);
  tbb::parallel_for(0, w * h, [&](int t) {
    if (s.cancellation) s.cancellation->ThrowIfCancelled();
    const int ix = t % w, iy = t / w;  // mu, y
    const LtcTexel &texel = fits[static_cast<size_t>(ix) * h + iy];
    PointValue v;
    Store(texel.minv, &v);
    lobes.Moments(s, mu[ix], ys[iy], &v);
    for (int k = 0; k < c; ++k) {
      table->values[static_cast<size_t>(t) * c + k] = v.value[k];
      table->errors[static_cast<size_t>(t) * c + k] = v.error[k];
    }
    const LtcErrors e = LtcPointErrors(lobes, s, mu[ix], ys[iy], v);
    table->fitMaps[static_cast<size_t>(t) * 3 + 0] = e.lobe;
    table->fitMaps[static_cast<size_t>(t) * 3 + 1] = e.polygon;
    table->fitMaps[static_cast<size_t>(t) * 3 + 2] = e.leakage;
    evaluations[t] = v.evaluations + static_cast<uint64_t>(texel.evaluations);
  });
  uint64_t sum = 0;
  for (uint64_t e : evaluations) sum += e;
  return sum;
}

Metadata LtcFitMetadata(const Table &table, const std::string &lobeErrorRule) {
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
           "magnitude D| dl / magnitude (" +
               lobeErrorRule +
               "); polygonError = max over 12 test rectangles receiving >= 2% of the lobe "
               "(clipped at the horizon) of |magnitude int_P D - int_P f (n.l)| / int_P f (n.l); "
               "leakage = int_{l.z<0} D dl (closed form)"}};
}

std::vector<double> LtcFitParameters(const double *v) {
  // A texel that reflects less than 1e-6 of the light (ltc_sheen's where the
  // lobe vanishes in double, or nearly: at small roughness and steep views)
  // renders nothing whatever its matrix: no branch to keep (check's jump
  // detector leaves it out). ltc_ggx's magnitude is at least 0.3.
  if (!(v[4] >= kLtcNoLight)) return {};
  const std::array<double, 4> p = LtcParameters({v[0], v[1], v[2], v[3]});
  return {p[0], p[1], p[2], p[3]};
}

std::string LtcTexelProblem(const double *v) {
  const LtcMatrix m{v[0], v[1], v[2], v[3]};
  if (m.Determinant() > 0.0) return "";
  return "det M^-1 = " + FormatDouble(m.Determinant()) + " <= 0 (the light renders black)";
}

void LtcDiffuseFresnel(const LtcLobe &lobe, const BakeSettings &s, double mu, PointValue *out) {
  if (s.estimator == Estimator::kAdaptiveQuadrature) {
    const LtcMomentsReference r = IntegrateLobeMomentsAdaptive(lobe, mu, AdaptiveTolerance(s));
    out->value[5] = r.fresnel;
    out->error[5] = r.fresnelBound;
    out->evaluations += r.evaluations;
    return;
  }
  double m1 = 0, f1 = 0, m2 = 0, f2 = 0;
  IntegrateLobeMoments(lobe, mu, 1, &m1, &f1);
  IntegrateLobeMoments(lobe, mu, 2, &m2, &f2);
  out->value[5] = f2;
  out->error[5] = std::fabs(f2 - f1) + 1e-12;
}

void AddLtcHeaderNotes(HeaderText *text, const std::string &magnitudeIs) {
  text->notes.push_back(
      "Linearly transformed cosines: M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] in the");
  text->notes.push_back(
      "frame n = +z, v = (sqrt(1 - mu^2), 0, mu); the lobe f (n.l) ~ magnitude D(l), a");
  text->notes.push_back("Schlick F gives F0 magnitude + (1 - F0) fresnel.");
  text->layout =
      "; channels m00, m20, m02, m22,\n"
      "// magnitude (= " +
      magnitudeIs + "), fresnel.\n";
}

bool FitsLobe(const TableDefinition &table) {
  return dynamic_cast<const LtcLobeFamily *>(&table) != nullptr;
}

LtcLobe FittedLobe(const TableDefinition &table, const BakeSettings &settings, double y) {
  const auto *lobes = dynamic_cast<const LtcLobeFamily *>(&table);
  if (!lobes) throw std::invalid_argument(std::string("table ") + table.Name() + " fits no lobe");
  return lobes->LobeAt(settings, y);
}

}  // namespace lutbake
