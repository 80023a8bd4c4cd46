// Fits the 64 x 64 GGX LTC table (issue 28, integrators/ltc_fit.h) and
// measures it, and ltc_code's published table as three.js samples it, with
// the same errors: lobe error, worst polygon (rectangle) error, leakage.
//
//   lutbake_measure_ltc [--threads N] [--leakage-weight W] [--no-errors]
//                       [--sheen charlie|ashikhmin [--alpha-r]]
//                       [--shipped OURS.js] [--points N] [RectAreaLightTexturesLib.js]
//
// --points N: at N pseudo-random points (mu, r) (a fixed sequence), table
// ltc_ggx as `lutbake eval` fits it (FitLtcPoint along the path of the
// default 64 x 64 texel-centre grid) against ltc_code's table sampled as
// three.js samples it, both measured alike; nothing else.
//
// --shipped measures lutbake's table as the threejs-ltc preset ships it
// (`lutbake bake --preset threejs-ltc`: its LTC_MAT_1 / LTC_MAT_2, float32,
// sampled as three.js samples them) in place of the table fitted here.
//
// --sheen fits the sheen lobe instead (alpha = r^2, or r with --alpha-r); it
// has no published table to compare with.
//
// The .js file is three.js's examples/jsm/lights/RectAreaLightTexturesLib.js
// (npm pack three); its LTC_MAT_1 / LTC_MAT_2 are ltc_code's
// fit/results/ltc.js. three.js samples them bilinearly (LinearFilter, float
// or half textures) at uv = (r, sqrt(1 - mu)) * 63/64 + 0.5/64, i.e. at
// texel coordinates (r, sqrt(1 - mu)) * 63 of texel centres: the table's
// texel (i, j) holds (mu_i, r_j) = (1 - (i/63)^2, j/63). The values are
// rounded to float as three.js's Float32Array holds them.
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lutbake/integrators/albedo_quadrature.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/models/sheen.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/validation/ltc_report.h"

using namespace lutbake;

namespace {

// The numbers of `const NAME = [ ... ];` ("- 4.5e-07" has a space after the sign).
std::vector<float> ReadArray(const std::string &text, const std::string &name) {
  std::vector<float> out;
  const size_t at = text.find("const " + name + " = [");
  if (at == std::string::npos) return out;
  const size_t begin = text.find('[', at) + 1, end = text.find(']', begin);
  std::string body = text.substr(begin, end - begin);
  std::string cleaned;
  for (size_t k = 0; k < body.size(); ++k) {
    if (body[k] == '-' && k + 1 < body.size() && body[k + 1] == ' ') {
      cleaned += '-';
      ++k;
      continue;
    }
    cleaned += body[k] == ',' ? ' ' : body[k];
  }
  std::istringstream in(cleaned);
  double v;
  while (in >> v) out.push_back(static_cast<float>(v));
  return out;
}

// M^-1 of a texture in three.js's layout (ThreejsLtcTexture) as three.js
// samples it at (r, sqrt(1 - mu)), and its magnitude there.
LtcMatrix FetchMatrix(const Table &texture, double r, double v) {
  return {Lookup(texture, r, v, 0), Lookup(texture, r, v, 1), Lookup(texture, r, v, 2),
          Lookup(texture, r, v, 3)};
}
double FetchMagnitude(const Table &texture, double r, double v) { return Lookup(texture, r, v, 4); }

struct Summary {
  double meanLobe = 0, maxLobe = 0, meanPolygon = 0, maxPolygon = 0, meanLeakage = 0,
         maxLeakage = 0;
};

Summary Summarise(const std::vector<LtcErrors> &e) {
  Summary s;
  for (const LtcErrors &x : e) {
    s.meanLobe += x.lobe;
    s.maxLobe = std::max(s.maxLobe, x.lobe);
    s.meanPolygon += x.polygon;
    s.maxPolygon = std::max(s.maxPolygon, x.polygon);
    s.meanLeakage += x.leakage;
    s.maxLeakage = std::max(s.maxLeakage, x.leakage);
  }
  const double n = static_cast<double>(e.size());
  s.meanLobe /= n;
  s.meanPolygon /= n;
  s.meanLeakage /= n;
  return s;
}

void Print(const char *name, const Summary &s) {
  std::printf(
      "%-34s lobe mean %.5f max %.5f | polygon mean %.5f max %.4f | leakage mean %.5f max %.4f\n",
      name, s.meanLobe, s.maxLobe, s.meanPolygon, s.maxPolygon, s.meanLeakage, s.maxLeakage);
}

}  // namespace

int main(int argc, char **argv) {
  int threads = 0;
  bool errors = true;
  LtcFitSettings settings;
  std::string jsPath, shippedPath;
  int points = 0;
  bool sheen = false, alphaIsR = false;
  SheenVisibility visibility = SheenVisibility::kCharlie;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--threads") && k + 1 < argc) {
      threads = std::atoi(argv[++k]);
    } else if (!std::strcmp(argv[k], "--leakage-weight") && k + 1 < argc) {
      settings.leakageWeight = std::atof(argv[++k]);
    } else if (!std::strcmp(argv[k], "--sheen") && k + 1 < argc) {
      sheen = true;
      if (!ParseSheenVisibility(argv[++k], &visibility)) {
        std::fprintf(stderr, "--sheen %s: charlie or ashikhmin\n", argv[k]);
        return 1;
      }
    } else if (!std::strcmp(argv[k], "--alpha-r")) {
      alphaIsR = true;
    } else if (!std::strcmp(argv[k], "--points") && k + 1 < argc) {
      points = std::atoi(argv[++k]);
    } else if (!std::strcmp(argv[k], "--shipped") && k + 1 < argc) {
      shippedPath = argv[++k];
    } else if (!std::strcmp(argv[k], "--no-errors")) {
      errors = false;
    } else {
      jsPath = argv[k];
    }
  }
  std::unique_ptr<tbb::global_control> control;
  if (threads > 0)
    control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    threads);
  const int size = 64;
  if (points > 0) {
    std::ifstream in(jsPath);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::vector<float> mat1 = ReadArray(buffer.str(), "LTC_MAT_1"),
                             mat2 = ReadArray(buffer.str(), "LTC_MAT_2");
    if (mat1.size() != 64 * 64 * 4 || mat2.size() != 64 * 64 * 4) {
      std::fprintf(stderr, "--points needs ltc_code's table (three.js's module)\n");
      return 1;
    }
    const Table theirTexture = ThreejsLtcTexture(mat1, mat2);
    std::vector<double> centres;
    for (int i = 0; i < size; ++i) centres.push_back((i + 0.5) / size);
    std::vector<double> mus(points), rs(points);
    uint64_t state = 0x9e3779b97f4a7c15ull;
    const auto next = [&] {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(state >> 11) * 0x1p-53;
    };
    for (int k = 0; k < points; ++k) mus[k] = next(), rs[k] = next();
    std::vector<LtcErrors> ours(points), theirs(points);
    LtcFitSettings fit = settings;
    fit.moments = false;
    const auto lobeAt = [](double r) {
      return MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
    };
    tbb::parallel_for(0, points, [&](int k) {
      const double mu = mus[k], r = rs[k];
      const LtcLobe lobe = lobeAt(r);
      double magnitude = 0, fresnel = 0;
      lobe.moments(mu, &magnitude, &fresnel);
      const std::vector<double> refs = RectangleLobeIntegrals(lobe, mu, 1);
      const LtcTexel t = FitLtcPoint(lobeAt, mu, r, centres, centres, fit);
      ours[k] = MeasureLtcErrors(lobe, mu, magnitude, t.minv, refs);
      const double v = std::sqrt(1.0 - mu);
      theirs[k] = MeasureLtcErrors(lobe, mu, magnitude, FetchMagnitude(theirTexture, r, v),
                                   FetchMatrix(theirTexture, r, v), refs);
    });
    const Summary so = Summarise(ours), st = Summarise(theirs);
    Print("lutbake eval (fitted at the point)", so);
    Print("ltc_code (as three.js samples it)", st);
    double worst = -1e300;
    for (int k = 0; k < points; ++k) worst = std::max(worst, ours[k].lobe - theirs[k].lobe);
    std::printf("%d points: ratios lobe %.3f, polygon %.3f, leakage %.3f; worst lobe excess %.5f\n",
                points, so.meanLobe / st.meanLobe, so.meanPolygon / st.meanPolygon,
                so.meanLeakage / st.meanLeakage, worst);
    return 0;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const LtcTable fitted =
      sheen ? FitSheenLtcTable(visibility, !alphaIsR, size, settings, false)
            : FitGgxLtcTable(NdfKind::kGgx, SmithForm::kCorrelated, size, settings, false);
  const double fitSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("fit 64x64 %s (leakage weight %g): %.2f s, %lld objective evaluations\n",
              sheen ? (alphaIsR ? "ltc_sheen, alpha = r" : "ltc_sheen, alpha = r^2") : "ltc_ggx",
              settings.leakageWeight, fitSeconds, static_cast<long long>(fitted.evaluations));
  auto lobeAt = [&](double r) {
    return sheen ? SheenLtcLobe(visibility, alphaIsR ? r : r * r)
                 : MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated);
  };
  double minDet = 1e300, maxMagnitudeError = 0, maxFresnelError = 0;
  bool finite = true;
  for (int k = 0; k < size * size; ++k) {
    const LtcMatrix m = fitted.Matrix(k);
    minDet = std::min(minDet, m.Determinant());
    for (double v : {m.m00, m.m20, m.m02, m.m22, fitted.magnitude[k], fitted.fresnel[k]})
      finite = finite && std::isfinite(v);
  }
  // magnitude and fresnel against the albedo quadrature at tolerance 1e-12.
  for (int i = 0; i < size && !sheen; ++i)
    for (int j = 1; j < size; ++j) {
      const double r = LtcTableRoughness(j, size);
      const SplitSumQuadrature q = IntegrateSplitSumQuadrature(
          Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated, LtcTableMu(i, size), 1e-12, true);
      const size_t k = static_cast<size_t>(i) * size + j;
      maxMagnitudeError = std::max(maxMagnitudeError, std::fabs(fitted.magnitude[k] - q.A - q.B));
      maxFresnelError = std::max(maxFresnelError, std::fabs(fitted.fresnel[k] - q.B));
    }
  std::printf("min det M^-1 %.3g, all finite %s", minDet, finite ? "yes" : "NO");
  if (!sheen)
    std::printf(", |magnitude - E| max %.2g, |fresnel - B| max %.2g", maxMagnitudeError,
                maxFresnelError);
  std::printf("\n");
  if (!errors) return 0;

  std::vector<float> mat1, mat2;
  if (!jsPath.empty() && !sheen) {
    std::ifstream in(jsPath);
    std::stringstream buffer;
    buffer << in.rdbuf();
    mat1 = ReadArray(buffer.str(), "LTC_MAT_1");
    mat2 = ReadArray(buffer.str(), "LTC_MAT_2");
    if (mat1.size() != 64 * 64 * 4 || mat2.size() != 64 * 64 * 4) {
      std::fprintf(stderr, "%s: LTC_MAT_1/2 not found or not 64x64x4\n", jsPath.c_str());
      return 1;
    }
  }
  // lutbake's shipped module: its texels replace the table fitted above.
  LtcTable table = fitted;
  if (!shippedPath.empty()) {
    std::ifstream in(shippedPath);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::vector<float> s1 = ReadArray(buffer.str(), "LTC_MAT_1"),
                             s2 = ReadArray(buffer.str(), "LTC_MAT_2");
    if (s1.size() != 64 * 64 * 4 || s2.size() != 64 * 64 * 4) {
      std::fprintf(stderr, "%s: LTC_MAT_1/2 not found or not 64x64x4\n", shippedPath.c_str());
      return 1;
    }
    for (size_t k = 0; k < s1.size() / 4; ++k) {
      table.m00[k] = s1[k * 4];
      table.m20[k] = s1[k * 4 + 1];
      table.m02[k] = s1[k * 4 + 2];
      table.m22[k] = s1[k * 4 + 3];
      table.magnitude[k] = s2[k * 4];
      table.fresnel[k] = s2[k * 4 + 1];
    }
    std::printf("measuring the shipped module %s\n", shippedPath.c_str());
  }
  const size_t count = static_cast<size_t>(size) * size;
  const Table theirTexture = mat1.empty() ? Table{} : ThreejsLtcTexture(mat1, mat2);
  std::vector<LtcErrors> ours(count), theirs(count), theirsExact(count);
  const auto t1 = std::chrono::steady_clock::now();
  tbb::parallel_for(size_t{0}, count, [&](size_t k) {
    const int i = static_cast<int>(k / size), j = static_cast<int>(k % size);
    const double mu = table.mu[i], r = table.roughness[j];
    const LtcLobe lobe = lobeAt(r);
    const std::vector<double> refs = RectangleLobeIntegrals(lobe, mu, 1);
    ours[k] = MeasureLtcErrors(lobe, mu, table.magnitude[k], table.Matrix(k), refs);
    if (!mat1.empty()) {
      const double v = std::sqrt(1.0 - mu);
      const LtcMatrix m = FetchMatrix(theirTexture, r, v);
      const double magnitude = FetchMagnitude(theirTexture, r, v);
      theirs[k] = MeasureLtcErrors(lobe, mu, table.magnitude[k], magnitude, m, refs);
      theirsExact[k] = MeasureLtcErrors(lobe, mu, table.magnitude[k], m, refs);
    }
  });
  std::printf("errors measured in %.1f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
  const Summary so = Summarise(ours);
  Print("lutbake", so);
  if (mat1.empty()) return 0;
  const Summary st = Summarise(theirs);
  Print("ltc_code (its magnitude)", st);
  Print("ltc_code (exact magnitude)", Summarise(theirsExact));
  // Per texel: lutbake's lobe error minus ltc_code's, ltc_code's D scaled by
  // its own magnitude (as three.js renders it) and by the exact one.
  for (const auto *other : {&theirs, &theirsExact}) {
    double worst = -1e300;
    int worstK = 0, worse = 0;
    for (size_t k = 0; k < count; ++k) {
      const double d = ours[k].lobe - (*other)[k].lobe;
      if (d > worst) {
        worst = d;
        worstK = static_cast<int>(k);
      }
      if (d > 0.005) ++worse;
    }
    std::printf(
        "worst lobe-error excess over ltc_code (%s magnitude) %.5f at texel (%d, %d); "
        "%d texels over 0.005\n",
        other == &theirs ? "its" : "exact", worst, worstK / size, worstK % size, worse);
  }
  if (std::getenv("LTC_DUMP")) {
    for (size_t k = 0; k < count; ++k)
      std::printf("T %d %d %.6f %.6f %.5f %.5f %.5f %.5f %.6f\n", static_cast<int>(k / size),
                  static_cast<int>(k % size), ours[k].lobe, theirs[k].lobe, ours[k].polygon,
                  theirs[k].polygon, ours[k].leakage, theirs[k].leakage, theirsExact[k].lobe);
  }
  // Between texels (three.js's bilinear sampling at the centres of the 63 x 63
  // cells, uv offset by half a texel): both tables interpolated, magnitude
  // included, against the lobe there (GGX only; the lobe error only).
  if (!sheen) {
    const int cells = size - 1;
    std::vector<float> oursTex1(static_cast<size_t>(size) * size * 4),
        oursTex2(static_cast<size_t>(size) * size * 4);
    for (size_t k = 0; k < count; ++k) {
      const LtcMatrix m = table.Matrix(static_cast<int>(k));
      const double v1[4] = {m.m00, m.m20, m.m02, m.m22};
      for (int c = 0; c < 4; ++c) oursTex1[k * 4 + c] = static_cast<float>(v1[c]);
      oursTex2[k * 4] = static_cast<float>(table.magnitude[k]);
    }
    const Table oursTexture = ThreejsLtcTexture(oursTex1, oursTex2);
    std::vector<double> midOurs(static_cast<size_t>(cells) * cells),
        midTheirs(static_cast<size_t>(cells) * cells);
    tbb::parallel_for(size_t{0}, midOurs.size(), [&](size_t k) {
      const double x = (k % cells) + 0.5, y = (k / cells) + 0.5;
      const double r = x / (size - 1), v = y / (size - 1), mu = 1.0 - v * v;
      const LtcLobe lobe = lobeAt(r);
      double magnitude = 0, fresnel = 0;
      lobe.moments(mu, &magnitude, &fresnel);
      auto error = [&](const Table &texture) {
        return LtcLobeError(lobe, mu, magnitude, FetchMagnitude(texture, r, v),
                            FetchMatrix(texture, r, v), 1);
      };
      midOurs[k] = error(oursTexture);
      midTheirs[k] = error(theirTexture);
    });
    double meanOurs = 0, meanTheirs = 0, worst = -1e300;
    int worse = 0;
    for (size_t k = 0; k < midOurs.size(); ++k) {
      meanOurs += midOurs[k] / midOurs.size();
      meanTheirs += midTheirs[k] / midOurs.size();
      worst = std::max(worst, midOurs[k] - midTheirs[k]);
      if (midOurs[k] - midTheirs[k] > 0.005) {
        ++worse;
        if (std::getenv("LTC_DUMP"))
          std::printf("M %zu %zu %.5f %.5f\n", k / cells, k % cells, midOurs[k], midTheirs[k]);
      }
    }
    std::printf(
        "between texels (bilinear, both magnitudes as stored): lobe mean lutbake %.5f, "
        "ltc_code %.5f (ratio %.3f); worst excess %.5f, %d of %zu cells over 0.005\n",
        meanOurs, meanTheirs, meanOurs / meanTheirs, worst, worse, midOurs.size());
  }
  std::printf("ratios lutbake / ltc_code: lobe %.3f, polygon %.3f, leakage %.3f\n",
              so.meanLobe / st.meanLobe, so.meanPolygon / st.meanPolygon,
              so.meanLeakage / st.meanLeakage);
  return 0;
}
