// Rectangular area lights end to end in a browser (issue 28): a headless
// Chromium WebGL2 page lights rectangles with the emitted GLSL (--shader
// glsl: lutbake_rect_light_ltc_ggx and its helpers) and the baked ltc_ggx
// (--size 32, read from ltc_ggx.exr and uploaded as an engine would: channels
// 0-3 as an RGBA32F texture, 4-5 as RG32F, linear filtering), one case per
// pixel of a 32 x 32 RGBA32F target. The cases come in from a data texture:
// unit N and V, perceptual roughness, four corners relative to the point, in
// a random world orientation. Per pixel:
//   R  lutbake_rect_light_ltc_ggx_f1, two-sided    (magnitude I)
//   G  lutbake_rect_light_ltc_ggx(F0 = 0.04, F90 = 1).x, two-sided
//   B  lutbake_rect_light_diffuse, two-sided       (int_P (n.l) / pi)
//   A  lutbake_rect_light_ltc_ggx_f1, one-sided    (0 when the light faces away)
// Two comparisons:
//   (a) every channel against the same LTC integral in double (models/ltc.h,
//       the table read by Lookup), within the float32 and filtering bound
//       derived in support/ltc_area_light_reference.h;
//   (b) at 48 texel centres, the 12 rectangles of the table's polygon error
//       (LtcTestRectangles, scaled and turned into the world) against the
//       quadrature of the true GGX lobe, int_P f (n.l) (RectangleLobeIntegrals,
//       the rule the stated error is measured with): within the texel's stated
//       polygonError (ltc_ggx.fit.exr) times the reference, plus (a)'s bound,
//       for the rectangles the statement covers (>= 2% of the lobe).
// Removing either clipping or flipping the one-sided sign in the emitted code
// fails this test (tried: docs/formats.md, "Rectangular area lights").
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/lutbake.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/headless_chromium.h"
#include "support/ltc_area_light_reference.h"
#include "support/webgl_page.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

constexpr int kTableSize = 32;
constexpr int kSize = 32;  // pixels: kSize x kSize cases
constexpr int kTexelsPerCase = 6;

const char *kPage = R"(
(async () => {
  const out = {};
  try {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = SIZE;
    const gl = canvas.getContext('webgl2');
    out.renderer = gl.getParameter(gl.RENDERER);
    out.floatTarget = !!gl.getExtension('EXT_color_buffer_float');
    out.floatLinear = !!gl.getExtension('OES_texture_float_linear');
    const upload = (unit, internal, format, width, height, data, filter) => {
      const t = gl.createTexture();
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, height, 0, format, gl.FLOAT,
                    new Float32Array(data));
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    };
    upload(0, gl.RGBA32F, gl.RGBA, sources.width, sources.height, sources.matrix, gl.LINEAR);
    upload(1, gl.RG32F, gl.RG, sources.width, sources.height, sources.moments, gl.LINEAR);
    upload(2, gl.RGBA32F, gl.RGBA, SIZE * TEXELS, SIZE, sources.cases, gl.NEAREST);
    const fs = `#version 300 es
precision highp float;
${sources.glsl}
uniform highp sampler2D ltc_matrix, ltc_moments, cases;
out vec4 color;
vec3 at(int k) {
  return texelFetch(cases, ivec2(int(gl_FragCoord.x) * ${TEXELS} + k, int(gl_FragCoord.y)), 0).xyz;
}
void main() {
  vec3 N = at(0), V = at(1), p0 = at(2), p1 = at(3), p2 = at(4), p3 = at(5);
  float r = texelFetch(cases, ivec2(int(gl_FragCoord.x) * ${TEXELS}, int(gl_FragCoord.y)), 0).w;
  color = vec4(
      lutbake_rect_light_ltc_ggx_f1(ltc_matrix, ltc_moments, N, V, r, p0, p1, p2, p3, true),
      lutbake_rect_light_ltc_ggx(ltc_matrix, ltc_moments, N, V, r, p0, p1, p2, p3, vec3(0.04),
                                 vec3(1.0), true).x,
      lutbake_rect_light_diffuse(N, V, p0, p1, p2, p3, true),
      lutbake_rect_light_ltc_ggx_f1(ltc_matrix, ltc_moments, N, V, r, p0, p1, p2, p3, false));
}`;
    lutbakeProgram(gl, fs, { ltc_matrix: 0, ltc_moments: 1, cases: 2 });
    out.pixels = lutbakeDrawPixels(gl, SIZE, 3, true);
    out.error = gl.getError();
  } catch (e) { out.exception = String(e && e.stack || e); }
  await fetch('http://127.0.0.1:LUTBAKE_RESULT_PORT/', { method: 'POST', body: JSON.stringify(out) });
})();
)";

// The cases: 48 texel centres x the 12 rectangles of the polygon error,
// then random rectangles at random (mu, r) up to kSize^2.
struct Cases {
  std::vector<test::AreaLightCase> all;
  std::vector<std::array<int, 2>> texel;  // (ix, iy) of a texel-centre case, else (-1, -1)
};
Cases MakeCases(const Table &ltc) {
  Cases out;
  std::mt19937 random(2028);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const std::vector<LtcRectangle> &rectangles = LtcTestRectangles();
  for (int ix = 2; ix < kTableSize; ix += 4)
    for (int iy : {1, 7, 13, 19, 25, 31})
      for (size_t k = 0; k < rectangles.size(); ++k) {
        const double scale = 0.5 + 19.5 * uniform(random);
        std::array<Vec3, 4> local;
        for (int v = 0; v < 4; ++v) local[v] = test::Scaled(rectangles[k].vertices[v], scale);
        test::AreaLightCase c = test::MakeCase(ltc.x.TexelCenter(ix), ltc.y.TexelCenter(iy), local,
                                               test::RandomRotation(random));
        c.rectangle = static_cast<int>(k);
        out.all.push_back(c);
        out.texel.push_back({ix, iy});
      }
  while (out.all.size() < static_cast<size_t>(kSize * kSize)) {
    const double mu = 0.02 + 0.975 * uniform(random), r = 0.02 + 0.98 * uniform(random);
    out.all.push_back(
        test::MakeCase(mu, r, test::RandomRectangle(random), test::RandomRotation(random)));
    out.texel.push_back({-1, -1});
  }
  return out;
}

TEST(BrowserAreaLight, WebGl2LightsRectanglesAsTheLtcIntegralAndTheQuadrature) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "chromium not found: the WebGL2 area lights are not rendered here "
                    "(scripts/setup.sh installs Debian's chromium)";
  const fs::path d = test::Scratch("browser_area_light");
  // --tables ltc_ggx --size 32 --format exr --shader glsl
  BakeRequest request = test::BakeRequestFor(d);
  request.tables = {"ltc_ggx"};
  request.size = kTableSize;
  request.formats = {"exr"};
  request.shaders = {"glsl"};
  Bake(request);
  const Table ltc = ReadExrTable((d / "ltc_ggx.exr").string());
  const Table fit = ReadExrTable((d / "ltc_ggx.fit.exr").string());
  ASSERT_EQ(ltc.channels, 6);
  ASSERT_EQ(ltc.width(), kTableSize);
  ASSERT_EQ(fit.channels, 3);
  const Cases cases = MakeCases(ltc);

  std::vector<float> matrix, moments, data;
  for (size_t t = 0; t < ltc.texelCount(); ++t) {
    for (int c = 0; c < 4; ++c) matrix.push_back(static_cast<float>(ltc.values[t * 6 + c]));
    for (int c = 4; c < 6; ++c) moments.push_back(static_cast<float>(ltc.values[t * 6 + c]));
  }
  for (const test::AreaLightCase &c : cases.all) {
    data.insert(data.end(), {c.N[0], c.N[1], c.N[2], c.r, c.V[0], c.V[1], c.V[2], 0.0f});
    for (int k = 0; k < 4; ++k) data.insert(data.end(), {c.p[k][0], c.p[k][1], c.p[k][2], 0.0f});
  }
  const nlohmann::json sources = {{"glsl", test::ReadWhole(d / "lutbake.glsl")},
                                  {"width", ltc.width()},
                                  {"height", ltc.height()},
                                  {"matrix", matrix},
                                  {"moments", moments},
                                  {"cases", data}};
  const std::string html =
      "<!doctype html><script type=\"module\">\nconst SIZE = " + std::to_string(kSize) +
      ", TEXELS = " + std::to_string(kTexelsPerCase) + ";\nconst sources = " + sources.dump() +
      ";\n" + test::kWebGlPageHelpers + kPage + "</script>\n";
  std::string log;
  const std::string body =
      test::RunPage(d, html, "--use-angle=swiftshader --enable-unsafe-swiftshader", "", 120, &log);
  ASSERT_FALSE(body.empty()) << log;
  const nlohmann::json page = nlohmann::json::parse(body);
  ASSERT_FALSE(page.contains("exception")) << page["exception"];
  ASSERT_EQ(page["error"], 0);
  ASSERT_TRUE(page["floatTarget"]) << "EXT_color_buffer_float is missing";
  ASSERT_TRUE(page["floatLinear"]) << "OES_texture_float_linear is missing";
  ASSERT_EQ(page["pixels"].size(), static_cast<size_t>(kSize * kSize * 4));

  // (b)'s references: the quadrature at each texel of the cases.
  std::map<std::pair<int, int>, std::vector<double>> references;
  for (const auto &texel : cases.texel) {
    if (texel[0] < 0 || references.count({texel[0], texel[1]})) continue;
    const double mu = ltc.x.TexelCenter(texel[0]), r = ltc.y.TexelCenter(texel[1]);
    references[{texel[0], texel[1]}] = RectangleLobeIntegrals(
        MicrofacetLtcLobe(Ndf{NdfKind::kGgx, r * r}, SmithForm::kCorrelated), mu, 0);
  }
  double worstRatio[4] = {0, 0, 0, 0}, worstRelative = 0.0, worstQuadrature = 0.0,
         worstQuadratureRatio = 0.0;
  std::vector<double> relativeBounds;
  double loosest = 0.0, loosestMu = 0.0, loosestR = 0.0;  // the largest bound / value
  int quadratureChecked = 0, lit = 0, unlit = 0;
  const char *names[4] = {"f1", "fresnel", "diffuse", "one-sided"};
  for (size_t i = 0; i < cases.all.size(); ++i) {
    const test::AreaLightCase &c = cases.all[i];
    const test::AreaLightExpected e = test::ExpectedAreaLight(ltc, c, 0.04);
    double got[4];
    for (int k = 0; k < 4; ++k) got[k] = page["pixels"][i * 4 + static_cast<size_t>(k)];
    const double want[4] = {e.f1, e.fresnel, e.diffuse, e.oneSided};
    const double bound[4] = {e.f1Bound, e.fresnelBound, e.diffuseBound, e.f1Bound};
    const int x = static_cast<int>(i) % kSize, y = static_cast<int>(i) / kSize;
    for (int k = 0; k < 4; ++k) {
      if (k == 3 && e.facingMargin < 1e-3) continue;  // nearly edge-on: the side is moot
      worstRatio[k] = std::max(worstRatio[k], std::abs(got[k] - want[k]) / bound[k]);
      if (want[k] > 1e-3) {
        worstRelative = std::max(worstRelative, std::abs(got[k] / want[k] - 1.0));
        relativeBounds.push_back(bound[k] / want[k]);
        if (bound[k] / want[k] > loosest) {
          loosest = bound[k] / want[k];
          loosestMu = c.mu;
          loosestR = c.r;
        }
      }
      EXPECT_LE(std::abs(got[k] - want[k]), bound[k])
          << names[k] << " at pixel (" << x << ", " << y << "): mu = " << c.mu << ", r = " << c.r
          << ", rectangle " << c.rectangle << ": WebGL2 " << got[k] << ", double " << want[k];
    }
    if (e.integral > 0) (e.oneSided > 0 ? lit : unlit) += 1;
    // (b) the true lobe, where the table states its polygon error.
    const auto &texel = cases.texel[i];
    if (texel[0] < 0) continue;
    const double reference = references[{texel[0], texel[1]}][static_cast<size_t>(c.rectangle)];
    const double magnitude = ltc.value(texel[0], texel[1], 4);
    if (!(reference >= kLtcPolygonMinimumShare * magnitude)) continue;
    const double stated = fit.value(texel[0], texel[1], 1);
    const double allowed = stated * reference + e.f1Bound + test::kFloatUnit * reference;
    ++quadratureChecked;
    worstQuadrature = std::max(worstQuadrature, std::abs(got[0] - reference) / reference);
    worstQuadratureRatio = std::max(worstQuadratureRatio, std::abs(got[0] - reference) / allowed);
    EXPECT_LE(std::abs(got[0] - reference), allowed)
        << "texel (" << texel[0] << ", " << texel[1] << ") rectangle " << c.rectangle << ": WebGL2 "
        << got[0] << ", quadrature " << reference << ", stated polygon error " << stated;
  }
  EXPECT_GT(lit, 50);
  EXPECT_GT(unlit, 50);
  EXPECT_GT(quadratureChecked, 200);
  std::sort(relativeBounds.begin(), relativeBounds.end());
  std::printf(
      "WebGL2 area lights (%s): %zu cases; (a) |WebGL2 - double| / bound, worst: f1 %.3g, "
      "fresnel %.3g, diffuse %.3g, one-sided %.3g (%d lit, %d facing away); worst relative "
      "%.3g (values > 1e-3; bound relative median %.3g, max %.3g at mu = %.3g, r = %.3g); (b) %d "
      "rectangles against "
      "the quadrature: worst relative %.3g, %.3g of the allowance\n",
      page["renderer"].get<std::string>().c_str(), cases.all.size(), worstRatio[0], worstRatio[1],
      worstRatio[2], worstRatio[3], lit, unlit, worstRelative,
      relativeBounds.empty() ? 0.0 : relativeBounds[relativeBounds.size() / 2],
      relativeBounds.empty() ? 0.0 : relativeBounds.back(), loosestMu, loosestR, quadratureChecked,
      worstQuadrature, worstQuadratureRatio);
  test::RemoveBrowserDirectory(d);
}

}  // namespace
}  // namespace lutbake
