// End to end in a browser (issue 16): a headless Chromium WebGL2 page loads
// the baked E, Eavg and dfg through the emitted ES modules (--format js-half:
// binary16 in Uint16Array, uploaded as R16F / RG16F textures with linear
// filtering, as three.js does with HalfFloatType) and shades with the
// emitted GLSL (--shader glsl: lutbake_sample_*, the split sum and the
// Kulla-Conty functions) a white furnace, a constant environment L = 1, on
// the 32 x 32 grid of (mu, r) = ((x + 0.5) / 32, (y + 0.5) / 32), the texel
// centres of the tables (--size 32). Per pixel, four channels:
//   R  F0 = F90 = 1:   A + B + F_ms(F_avg = 1, E_avg) (1 - E)   (the furnace: ~1)
//   G  F0 = 0.04:      0.04 A + B + F_ms(F_avg(0.04), E_avg) (1 - E)
//   B  F0 = 0.5:       0.5 A + B                               (split sum alone)
//   A  F0 = 0.5:       F_ms(F_avg(0.5), E_avg) (1 - E)          (Kulla-Conty alone)
// F_avg = 20/21 F0 + 1/21 (Schlick), F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)).
// They are rendered into an RGBA32F framebuffer (EXT_color_buffer_float; an
// RGBA8 one if it is missing), read back and compared with the same
// expressions in double over lutbake's own values (the float32 EXR of the
// same bake, bounds below 4e-8).
//
// Tolerance, per pixel and channel: the half storage moves each of A, B, E,
// E_avg by at most 2^-11 |v| (half an ulp of binary16; 2^-25 below 2^-14);
// the allowance is the largest change of the channel's expression with every
// input at either end of its interval (the expressions are monotonic in each
// input over so small a box), plus 2^-18 = 3.8e-6 for the GPU's float32
// arithmetic (~10 operations of values <= 1.1), plus 0.5/255 with an RGBA8
// target. At texel centres the bilinear weights are 0, so filtering adds
// nothing. A lookup off by half a texel (or remapped by (N - 1) / N, the
// convention of tables sampled at their edges) reads the average of two
// neighbours instead: B = (1 - mu)^5-like near mu = 0 changes by ~0.1 per
// texel there, ~50 times the largest allowance, so the test fails (tried:
// see docs/formats.md, "Browser test"). The page posts its pixels to a loopback
// server (support/headless_chromium.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lutbake/formats/table_reader.h"
#include "lutbake/lutbake.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/headless_chromium.h"
#include "support/webgl_page.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

std::string ReadText(const fs::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

constexpr int kSize = 32;

// The four channels at (A, B, E, Eavg).
std::array<double, 4> Furnace(double A, double B, double E, double Eavg) {
  const auto fms = [&](double F0) {
    const double favg = 20.0 / 21.0 * F0 + 1.0 / 21.0;
    return favg * favg * Eavg / (1.0 - favg * (1.0 - Eavg)) * std::max(1.0 - E, 0.0);
  };
  return {A + B + fms(1.0), 0.04 * A + B + fms(0.04), 0.5 * A + B, fms(0.5)};
}

const char *kPage = R"(
(async () => {
  const out = {};
  try {
    const load = text => import(URL.createObjectURL(new Blob([text], { type: 'text/javascript' })));
    const E = await load(sources.E), Eavg = await load(sources.Eavg), dfg = await load(sources.dfg);
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = SIZE;
    const gl = canvas.getContext('webgl2');
    out.renderer = gl.getParameter(gl.RENDERER);
    const floatTarget = !!gl.getExtension('EXT_color_buffer_float');
    out.target = floatTarget ? 'RGBA32F' : 'RGBA8';
    const upload = (m, unit) => {
      const t = gl.createTexture();
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      const [internal, format] = m.channels === 1 ? [gl.R16F, gl.RED] : [gl.RG16F, gl.RG];
      gl.texImage2D(gl.TEXTURE_2D, 0, internal, m.width, m.height * m.depth, 0, format,
                    gl.HALF_FLOAT, m.data);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    };
    upload(E.default, 0); upload(Eavg.default, 1); upload(dfg.default, 2);
    const fs = `#version 300 es
precision highp float;
${sources.glsl}
uniform highp sampler2D E_tex, Eavg_tex, dfg_tex;
out vec4 color;
vec3 ms(vec3 F0, float E, float Eavg) {
  return lutbake_fresnel_ms(lutbake_favg_schlick(F0, vec3(1.0)), Eavg) * lutbake_ms_albedo(E);
}
void main() {
  float mu = gl_FragCoord.x / float(${SIZE});
  float r = gl_FragCoord.y / float(${SIZE});
  vec2 AB = lutbake_sample_dfg(dfg_tex, mu, r);
  float E = lutbake_sample_E(E_tex, mu, r);
  float Eavg = lutbake_sample_Eavg(Eavg_tex, r);
  vec3 one = vec3(1.0);
  float white = (lutbake_specular_albedo(AB, one, one) + ms(one, E, Eavg)).x;
  float tinted = (lutbake_specular_albedo(AB, vec3(0.04), one) + ms(vec3(0.04), E, Eavg)).x;
  color = vec4(white, tinted, lutbake_specular_albedo(AB, vec3(0.5), one).x,
               ms(vec3(0.5), E, Eavg).x);
}`;
    lutbakeProgram(gl, fs, { E_tex: 0, Eavg_tex: 1, dfg_tex: 2 });
    out.pixels = lutbakeDrawPixels(gl, SIZE, 3, floatTarget);
    out.error = gl.getError();
  } catch (e) { out.exception = String(e && e.stack || e); }
  await fetch('http://127.0.0.1:LUTBAKE_RESULT_PORT/', { method: 'POST', body: JSON.stringify(out) });
})();
)";

TEST(BrowserFurnace, WebGl2ShadesTheFurnaceFromTheEmittedModuleAndGlsl) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "chromium not found: the WebGL2 furnace is not rendered here "
                    "(scripts/setup.sh installs Debian's chromium)";
  const fs::path d = test::Scratch("browser_furnace");
  // --tables E,Eavg,dfg --size kSize --format exr,js-half --shader glsl
  BakeRequest request = test::BakeRequestFor(d);
  request.tables = {"E", "Eavg", "dfg"};
  request.size = kSize;
  request.formats = {"exr", "js-half"};
  request.shaders = {"glsl"};
  Bake(request);
  const nlohmann::json sources = {{"E", ReadText(d / "E.js")},
                                  {"Eavg", ReadText(d / "Eavg.js")},
                                  {"dfg", ReadText(d / "dfg.js")},
                                  {"glsl", ReadText(d / "lutbake.glsl")}};
  const std::string html =
      "<!doctype html><script type=\"module\">\nconst SIZE = " + std::to_string(kSize) +
      ";\nconst sources = " + sources.dump() + ";\n" + test::kWebGlPageHelpers + kPage +
      "</script>\n";
  std::string log;
  const std::string body =
      test::RunPage(d, html, "--use-angle=swiftshader --enable-unsafe-swiftshader", "", 120, &log);
  ASSERT_FALSE(body.empty()) << log;
  const nlohmann::json page = nlohmann::json::parse(body);
  ASSERT_FALSE(page.contains("exception")) << page["exception"];
  ASSERT_EQ(page["error"], 0);
  const bool floatTarget = page["target"] == "RGBA32F";
  ASSERT_EQ(page["pixels"].size(), static_cast<size_t>(kSize * kSize * 4));

  const Table E = ReadExrTable((d / "E.exr").string());
  const Table Eavg = ReadExrTable((d / "Eavg.exr").string());
  const Table dfg = ReadExrTable((d / "dfg.exr").string());
  ASSERT_EQ(dfg.width(), kSize);
  ASSERT_EQ(E.width(), kSize);
  const auto halfStep = [](double v) { return std::max(std::abs(v) * 0x1p-11, 0x1p-25); };
  double worst = 0.0, worstAllowed = 0.0, furnaceWorst = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double in[4] = {dfg.value(x, y, 0), dfg.value(x, y, 1), E.value(x, y),
                            Eavg.value(y, 0)};
      const std::array<double, 4> want = Furnace(in[0], in[1], in[2], in[3]);
      std::array<double, 4> allowed = {0, 0, 0, 0};
      for (int corner = 0; corner < 16; ++corner) {
        double v[4];
        for (int k = 0; k < 4; ++k) v[k] = in[k] + ((corner >> k) & 1 ? 1 : -1) * halfStep(in[k]);
        const std::array<double, 4> moved = Furnace(v[0], v[1], v[2], v[3]);
        for (int c = 0; c < 4; ++c) allowed[c] = std::max(allowed[c], std::abs(moved[c] - want[c]));
      }
      for (int c = 0; c < 4; ++c) {
        const double a = allowed[c] + 0x1p-18 + (floatTarget ? 0.0 : 0.5 / 255.0);
        const double got = page["pixels"][static_cast<size_t>((y * kSize + x) * 4 + c)];
        const double expected = floatTarget ? want[c] : std::clamp(want[c], 0.0, 1.0);
        worst = std::max(worst, std::abs(got - expected));
        worstAllowed = std::max(worstAllowed, a);
        if (c == 0) furnaceWorst = std::max(furnaceWorst, std::abs(got - 1.0));
        ASSERT_LE(std::abs(got - expected), a)
            << "pixel (" << x << ", " << y << ") channel " << c << ": mu = " << (x + 0.5) / kSize
            << ", r = " << (y + 0.5) / kSize << ", rendered " << got << ", lutbake " << expected;
      }
    }
  std::printf(
      "WebGL2 furnace (%s, %s): worst |rendered - lutbake| %.3g (allowed up to %.3g); "
      "white furnace within %.3g of 1\n",
      page["target"].get<std::string>().c_str(), page["renderer"].get<std::string>().c_str(), worst,
      worstAllowed, furnaceWorst);
  test::RemoveBrowserDirectory(d);
}

}  // namespace
}  // namespace lutbake
