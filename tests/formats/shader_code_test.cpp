// The emitted shader code (--shader, lutbake.<ext>) and the constant-array
// embeddings (--format *-array, T.<ext>) compiled by real compilers:
//   GLSL  glslangValidator: GLSL 4.50 to SPIR-V (then spirv-val), and GLSL ES
//         3.00 (WebGL2) validated;
//   HLSL  glslangValidator -D: HLSL to SPIR-V (then spirv-val);
//   WGSL  Tint, Chromium's WebGPU compiler: createShaderModule and
//         getCompilationInfo in headless Chromium on SwiftShader's Vulkan
//         (Tint's whole front end: parsing, resolution, types, uniformity; a
//         render pipeline is not built: on SwiftShader it did not finish
//         within the headless run);
//   MSL   no Metal compiler runs on Linux: compiled as C++17 by clang++
//         against tests/formats/metal_shim/metal_stdlib (what that checks
//         and what it cannot is said there) and run: its lookups against
//         the library's Lookup at texel centres, half-way points and random
//         points.
// Each shader has an entry point that calls every emitted function, so that
// none is left out of the SPIR-V. A test skips (and says why) only when its
// tool is not installed; scripts/setup.sh installs glslang-tools,
// spirv-tools and chromium.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "lutbake/formats/fit_format.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/tables/lookup.h"
#include "support/cli_run.h"
#include "support/headless_chromium.h"
#include "support/ltc_area_light_reference.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

using test::RunCommand;

bool Have(const char *tool) {
  return std::system(("command -v " + std::string(tool) + " >/dev/null 2>&1").c_str()) == 0;
}

std::string ReadText(const fs::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every kind of table a set holds: 1D (Eavg), 2D with one and two channels
// (E, dfg, f82, sheen_E), 3D (glass_E, three eta slices), a listed
// roughness axis (a bake plan's E), and six channels (ltc_ggx, read as two
// textures; it brings the area-light functions).
const std::vector<Table> &Tables() {
  static const std::vector<Table> tables = [] {
    std::vector<Table> t;
    for (const char *name : {"E", "Eavg", "dfg", "f82", "sheen_E"})
      t.push_back(test::SmallTableOf(TableNamed(name)));
    BakeSettings s;
    s.size = 4;
    s.depthSize = 3;
    s.samples = 64;
    s.commandLine = "lutbake bake --test";
    t.push_back(BakeTable(TableNamed("glass_E"), s));
    Table listed = test::SmallTableOf(TableNamed("E"));
    listed.name = "E_listed";
    listed.y = ListedAxis("perceptualRoughness", {0.1, 0.35, 0.9});
    listed.values.resize(static_cast<size_t>(listed.width()) * 3);
    for (size_t i = 0; i < listed.values.size(); ++i)
      listed.values[i] = 0.5 + 0.4 * std::sin(0.7 * static_cast<double>(i));
    listed.errors.assign(listed.values.size(), 1e-7);
    for (auto &[key, value] : listed.metadata)
      if (key == "axisY") value = DescribeAxis(listed.y);
    t.push_back(listed);
    t.push_back(test::SmallTableOf(TableNamed("ltc_ggx")));
    return t;
  }();
  return tables;
}

// The fits lutbake emits (tests/data/fits, --format fit) of a 2D table with
// the corner map and two channels, of a 1D table, and of sheen_E in logs.
const std::vector<FitSource> &Fits() {
  static const std::vector<FitSource> fits = [] {
    std::vector<FitSource> f;
    for (const char *name : {"dfg", "Eavg", "f82", "sheen_E"})
      f.push_back(ReadFitSource(std::string(LUTBAKE_TEST_DATA) + "/fits/" + name + "_fit.h"));
    return f;
  }();
  return fits;
}

// The emitted code of one language: the arrays of every table, the fits'
// functions (--format fit-<language>), then lutbake.<ext>.
std::string EmittedCode(ShaderLanguage language, const fs::path &dir) {
  std::string code;
  for (const FitSource &f : Fits())
    code += FitShaderSource(language, f.name,
                            f.fit.dims == 2 ? std::vector<std::string>{"mu", "roughness"}
                                            : std::vector<std::string>{"roughness"},
                            f.fit, {}, {});
  for (const Table &t : Tables()) {
    if (t.channels > 4) continue;  // no array format holds six channels
    const fs::path path = dir / (t.Name() + ShaderExtension(language));
    MakeShaderArrayWriter(language)->Write(t, path.string(), {});
    code += ReadText(path);
  }
  const fs::path path = dir / (std::string("lutbake") + ShaderExtension(language));
  WriteShaderCode(path.string(), language, Tables(), {{"commandLine", "lutbake bake --test"}});
  return code + ReadText(path);
}

// The channel groups a table is read in: one texture of up to four channels
// each (first channel, count).
std::vector<std::pair<int, int>> ChannelGroups(const Table &t) {
  std::vector<std::pair<int, int>> groups;
  for (int first = 0; first < t.channels; first += 4)
    groups.emplace_back(first, std::min(4, t.channels - first));
  return groups;
}

// The name of table i's texture of group g: t<i>, or t<i>_<g> for a table
// read as several textures.
std::string TextureName(size_t i, size_t g) {
  return "t" + std::to_string(i) + (Tables()[i].channels > 4 ? "_" + std::to_string(g) : "");
}

std::vector<std::string> TextureNames() {
  std::vector<std::string> names;
  for (size_t i = 0; i < Tables().size(); ++i)
    for (size_t g = 0; g < ChannelGroups(Tables()[i]).size(); ++g)
      names.push_back(TextureName(i, g));
  return names;
}

// The lookup function of table t's channels [first, first + count).
std::string SampleName(const Table &t, int first, int count) {
  if (t.channels <= 4) return "lutbake_sample_" + t.Name();
  return "lutbake_sample_" + t.Name() + "_ch" + std::to_string(first) + "_" +
         std::to_string(first + count - 1);
}

// Calls of every emitted function, each adding its first component to
// `acc`, in the language's syntax; texture i is t<i> (and t<i>_sampler).
std::string Calls(ShaderLanguage language) {
  const bool wgsl = language == ShaderLanguage::kWgsl;
  const auto vec = [&](int n, const std::string &v) {
    switch (language) {
      case ShaderLanguage::kGlsl: return "vec" + std::to_string(n) + "(" + v + ")";
      case ShaderLanguage::kWgsl: return "vec" + std::to_string(n) + "<f32>(" + v + ")";
      default: return "float" + std::to_string(n) + "(" + v + ")";
    }
  };
  const auto lit = [&](const char *v) {
    return language == ShaderLanguage::kHlsl || language == ShaderLanguage::kMsl
               ? std::string(v) + "f"
               : std::string(v);
  };
  const auto tex = [&](const std::string &name) {
    return language == ShaderLanguage::kGlsl ? name : name + ", " + name + "_sampler";
  };
  std::string s;
  const auto add = [&](const std::string &call, int channels) {
    s += wgsl ? "  acc = acc + " : "  acc += ";
    s += call + (channels > 1 ? ".x" : "") + ";\n";
  };
  size_t i = 0;
  std::string E, Eavg, ltc;
  for (const Table &t : Tables()) {
    std::string coords;
    for (size_t a = 0; a < 1u + t.is2D() + t.is3D(); ++a) coords += ", " + lit("0.37");
    const std::vector<std::pair<int, int>> groups = ChannelGroups(t);
    for (size_t g = 0; g < groups.size(); ++g)
      add(SampleName(t, groups[g].first, groups[g].second) + "(" + tex(TextureName(i, g)) + coords +
              ")",
          groups[g].second);
    if (t.channels > 4) {
      ltc = tex(TextureName(i, 0)) + ", " + tex(TextureName(i, 1));
      ++i;
      continue;
    }
    add("lookup_" + t.Name() + "(" + coords.substr(2) + ")", t.channels);
    if (t.Name() == "E") E = tex(TextureName(i, 0));
    if (t.Name() == "Eavg") Eavg = tex(TextureName(i, 0));
    ++i;
  }
  const std::string v2 = vec(2, lit("0.5") + ", " + lit("0.25")),
                    one = vec(3, lit("1.0") + ", " + lit("1.0") + ", " + lit("1.0")),
                    f0 = vec(3, lit("0.04") + ", " + lit("0.5") + ", " + lit("0.9"));
  add("lutbake_specular_albedo(" + v2 + ", " + f0 + ", " + one + ")", 3);
  add("lutbake_f82_tint_a(" + f0 + ", " + f0 + ")", 3);
  add("lutbake_specular_albedo_f82(" + v2 + ", " + lit("0.01") + ", " + f0 + ", " + one + ", " +
          f0 + ")",
      3);
  add("lutbake_f_ms(" + lit("0.9") + ", " + lit("0.8") + ", " + lit("0.85") + ")", 1);
  add("lutbake_ms_albedo(" + lit("0.9") + ")", 1);
  add("lutbake_fresnel_ms(" + f0 + ", " + lit("0.85") + ")", 3);
  add("lutbake_favg_schlick(" + f0 + ", " + one + ")", 3);
  add("lutbake_f_ms_E(" + E + ", " + Eavg + ", " + lit("0.3") + ", " + lit("0.6") + ", " +
          lit("0.5") + ")",
      1);
  add("lutbake_sheen_albedo_scaling(" + f0 + ", " + lit("0.3") + ")", 1);
  for (const FitSource &f : Fits())
    add("lutbake_fit_" + f.name + "(" + lit("0.37") + (f.fit.dims == 2 ? ", " + lit("0.37") : "") +
            ")",
        f.fit.channels);
  add("lutbake_sheen_albedo_scaling2(" + f0 + ", " + lit("0.3") + ", " + lit("0.4") + ")", 1);
  // The area-light functions of ltc_ggx.
  const std::string N = vec(3, lit("0.0") + ", " + lit("0.0") + ", " + lit("1.0")),
                    V = vec(3, lit("0.6") + ", " + lit("0.0") + ", " + lit("0.8")),
                    corners = vec(3, lit("-1.0") + ", " + lit("-1.0") + ", " + lit("2.0")) + ", " +
                              vec(3, lit("1.0") + ", " + lit("-1.0") + ", " + lit("2.0")) + ", " +
                              vec(3, lit("1.0") + ", " + lit("1.0") + ", " + lit("2.0")) + ", " +
                              vec(3, lit("-1.0") + ", " + lit("1.0") + ", " + lit("-0.5")),
                    minv = vec(
                        4, lit("1.2") + ", " + lit("0.1") + ", " + lit("-0.3") + ", " + lit("0.9"));
  add("lutbake_ltc_edge(" + N + ", " + V + ")", 1);
  add("lutbake_ltc_polygon(" + minv + ", " + corners + ")", 1);
  add("lutbake_ltc_rect_form_factor(" + minv + ", " + N + ", " + V + ", " + corners + ", true)", 1);
  add("lutbake_rect_light_diffuse(" + N + ", " + V + ", " + corners + ", false)", 1);
  add("lutbake_rect_light_ltc_ggx(" + ltc + ", " + N + ", " + V + ", " + lit("0.4") + ", " +
          corners + ", " + f0 + ", " + one + ", true)",
      3);
  add("lutbake_rect_light_ltc_ggx_f1(" + ltc + ", " + N + ", " + V + ", " + lit("0.4") + ", " +
          corners + ", false)",
      1);
  return s;
}

// A float32 printed to round-trip, always with a '.' or an exponent.
std::string FloatText(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(static_cast<float>(v)));
  const std::string s = text;
  return s.find_first_of(".e") == std::string::npos ? s + ".0" : s;
}

TEST(ShaderCode, EmitsOnlyTheFunctionsOfTheBakedTables) {
  const fs::path dir = test::FormatTempDir("shader_only");
  const std::vector<Table> justE = {Tables()[0]};
  WriteShaderCode((dir / "a.glsl").string(), ShaderLanguage::kGlsl, justE, {});
  const std::string a = ReadText(dir / "a.glsl");
  EXPECT_NE(a.find("float lutbake_sample_E("), std::string::npos);
  for (const char *absent : {"lutbake_f_ms", "lutbake_specular_albedo", "lutbake_sheen", "f82",
                             "lutbake_ltc", "lutbake_rect_light"})
    EXPECT_EQ(a.find(absent), std::string::npos) << absent;
  // ltc_ggx alone: its two lookups (channels 0-3 and 4-5, no six-channel
  // one) and the area-light functions, nothing of the other tables.
  WriteShaderCode((dir / "c.glsl").string(), ShaderLanguage::kGlsl, {Tables().back()}, {});
  const std::string c = ReadText(dir / "c.glsl");
  for (const char *present :
       {"vec4 lutbake_sample_ltc_ggx_ch0_3(highp sampler2D ltc_ggx_ch0_3_texture, float mu",
        "vec2 lutbake_sample_ltc_ggx_ch4_5(", "float lutbake_ltc_edge(",
        "float lutbake_ltc_polygon(", "float lutbake_ltc_rect_form_factor(",
        "float lutbake_rect_light_diffuse(", "vec3 lutbake_rect_light_ltc_ggx(",
        "float lutbake_rect_light_ltc_ggx_f1("})
    EXPECT_NE(c.find(present), std::string::npos) << present;
  for (const char *absent : {"lutbake_sample_ltc_ggx(", "vec6", "lutbake_f_ms", "lutbake_sheen"})
    EXPECT_EQ(c.find(absent), std::string::npos) << absent;
  // dfg without f82: the split sum, no F82 term.
  WriteShaderCode((dir / "b.glsl").string(), ShaderLanguage::kGlsl, {Tables()[2]}, {});
  const std::string b = ReadText(dir / "b.glsl");
  EXPECT_NE(b.find("vec3 lutbake_specular_albedo("), std::string::npos);
  EXPECT_EQ(b.find("lutbake_specular_albedo_f82"), std::string::npos);
  // The texel-centre convention on a linear axis: u = (mu - 0) / (1 - 0),
  // clamped to the first and last centres of 6 texels.
  EXPECT_NE(b.find("clamp((mu - 0.0) * 1.0, 0.0833333358, 0.916666687)"), std::string::npos) << b;
}

TEST(ShaderCode, GlslCompilesToValidSpirvAndAsGlslEs300) {
  if (!Have("glslangValidator") || !Have("spirv-val"))
    GTEST_SKIP() << "glslangValidator or spirv-val not found (scripts/setup.sh installs "
                    "glslang-tools and spirv-tools)";
  const fs::path dir = test::FormatTempDir("shader_glsl");
  const std::string code = EmittedCode(ShaderLanguage::kGlsl, dir);
  std::string uniforms450, uniforms300;
  for (size_t i = 0; i < TextureNames().size(); ++i) {
    uniforms450 += "layout(binding = " + std::to_string(i) + ") uniform sampler2D " +
                   TextureNames()[i] + ";\n";
    uniforms300 += "uniform highp sampler2D " + TextureNames()[i] + ";\n";
  }
  const std::string body = "void main() {\n  float acc = 0.0;\n" + Calls(ShaderLanguage::kGlsl) +
                           "  color = vec4(acc);\n}\n";
  std::ofstream(dir / "test450.frag")
      << "#version 450\n"
      << code << uniforms450 << "layout(location = 0) out vec4 color;\n"
      << body;
  std::ofstream(dir / "test300.frag") << "#version 300 es\nprecision highp float;\n"
                                      << code << uniforms300 << "out vec4 color;\n"
                                      << body;
  int status = 0;
  std::string out = RunCommand("glslangValidator -V '" + (dir / "test450.frag").string() +
                                   "' -o '" + (dir / "glsl.spv").string() + "' 2>&1",
                               &status);
  ASSERT_EQ(status, 0) << out;
  out = RunCommand("spirv-val '" + (dir / "glsl.spv").string() + "' 2>&1", &status);
  EXPECT_EQ(status, 0) << out;
  out = RunCommand("glslangValidator '" + (dir / "test300.frag").string() + "' 2>&1", &status);
  EXPECT_EQ(status, 0) << out;
}

TEST(ShaderCode, HlslCompilesToValidSpirv) {
  if (!Have("glslangValidator") || !Have("spirv-val"))
    GTEST_SKIP() << "glslangValidator or spirv-val not found (scripts/setup.sh installs "
                    "glslang-tools and spirv-tools)";
  const fs::path dir = test::FormatTempDir("shader_hlsl");
  std::string resources;
  for (size_t i = 0; i < TextureNames().size(); ++i) {
    const std::string n = std::to_string(i), t = TextureNames()[i];
    resources += "Texture2D<float4> " + t + " : register(t" + n + ");\nSamplerState " + t +
                 "_sampler : register(s" + n + ");\n";
  }
  std::ofstream(dir / "test.hlsl")
      << EmittedCode(ShaderLanguage::kHlsl, dir) << resources
      << "float4 main() : SV_Target {\n  float acc = 0.0f;\n"
      << Calls(ShaderLanguage::kHlsl) << "  return float4(acc, acc, acc, acc);\n}\n";
  int status = 0;
  std::string out =
      RunCommand("glslangValidator -D -V -S frag -e main '" + (dir / "test.hlsl").string() +
                     "' -o '" + (dir / "hlsl.spv").string() + "' 2>&1",
                 &status);
  ASSERT_EQ(status, 0) << out;
  out = RunCommand("spirv-val '" + (dir / "hlsl.spv").string() + "' 2>&1", &status);
  EXPECT_EQ(status, 0) << out;
}

// Headless Chromium with WebGPU on SwiftShader's Vulkan (the driver Chromium
// ships): Tint compiles the module; its messages and any validation error
// come back on the console.
TEST(ShaderCode, WgslCompilesWithTint) {
  if (!Have("chromium"))
    GTEST_SKIP() << "chromium not found: WGSL is not compiled here (scripts/setup.sh installs "
                    "chromium)";
  const fs::path dir = test::FormatTempDir("shader_wgsl");
  std::string resources;
  for (size_t i = 0; i < TextureNames().size(); ++i) {
    const std::string t = TextureNames()[i];
    resources += "@group(0) @binding(" + std::to_string(2 * i) + ") var " + t +
                 ": texture_2d<f32>;\n@group(0) @binding(" + std::to_string(2 * i + 1) + ") var " +
                 t + "_sampler: sampler;\n";
  }
  const std::string wgsl =
      EmittedCode(ShaderLanguage::kWgsl, dir) + resources +
      "@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) "
      "vec4<f32> {\n  return vec4<f32>(f32(i), 0.0, 0.0, 1.0);\n}\n"
      "@fragment fn fs() -> @location(0) vec4<f32> {\n  var acc: f32 = 0.0;\n" +
      Calls(ShaderLanguage::kWgsl) + "  return vec4<f32>(acc);\n}\n";
  std::ofstream(dir / "test.wgsl") << wgsl;
  // The good module, and one with a type error that Tint must report.
  const nlohmann::json sources = {wgsl, "fn broken() -> f32 { return 1u; }\n"};
  const std::string page = "<!doctype html><script>\nconst sources = " + sources.dump() + ";\n" +
                           R"((async () => {
  const out = { adapter: false, modules: [] };
  try {
    const adapter = await navigator.gpu.requestAdapter();
    out.adapter = !!adapter;
    const device = await adapter.requestDevice();
    for (const code of sources) {
      device.pushErrorScope('validation');
      const module = device.createShaderModule({ code });
      const info = await module.getCompilationInfo();
      const entry = { messages: info.messages.map(m => `${m.type} ${m.lineNum}:${m.linePos} ${m.message}`) };
      const error = await device.popErrorScope();
      entry.error = error ? error.message : null;
      out.modules.push(entry);
    }
  } catch (e) { out.exception = String(e); }
  await fetch('http://127.0.0.1:LUTBAKE_RESULT_PORT/', { method: 'POST', body: JSON.stringify(out) });
})();
</script>)";
  std::string log;
  const std::string body =
      test::RunPage(dir, page,
                    "--enable-unsafe-webgpu --enable-features=Vulkan --use-vulkan=swiftshader "
                    "--use-webgpu-adapter=swiftshader",
                    "VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json", 120, &log);
  ASSERT_FALSE(body.empty()) << log;
  const nlohmann::json result = nlohmann::json::parse(body);
  ASSERT_EQ(result["adapter"], true) << result.dump(1);
  ASSERT_EQ(result["modules"].size(), 2u) << result.dump(1);
  EXPECT_EQ(result["modules"][0]["messages"].size(), 0u) << result.dump(1);
  EXPECT_TRUE(result["modules"][0]["error"].is_null()) << result.dump(1);
  // The broken one: Tint's message, so a compiler that accepts anything fails here.
  ASSERT_EQ(result["modules"][1]["messages"].size(), 1u) << result.dump(1);
  EXPECT_NE(result["modules"][1]["messages"][0].get<std::string>().find("return"),
            std::string::npos)
      << result.dump(1);
}

// The declaration of a shim texture `name` holding channels [first, first +
// count) of table t (the others 0) and its sampler.
std::string MetalTexture(const Table &t, const std::string &name, int first, int count) {
  std::ostringstream out;
  out << "  texture2d<float> " << name << ";\n  " << name << ".width = " << t.width() << ";\n  "
      << name << ".height = " << t.height() * t.depth() << ";\n  " << name << ".texels = {";
  for (size_t i = 0; i < t.texelCount(); ++i)
    for (int c = 0; c < 4; ++c)
      out << FloatText(c < count ? t.values[i * t.channels + first + c] : 0.0) << "f, ";
  out << "};\n  sampler " << name << "_sampler;\n";
  return out.str();
}

// Compiles main.cpp (the emitted Metal code and a main) in `dir` against the
// shim and runs it: its output, or "" with the compiler's in *failure.
std::string CompileAndRunMetal(const fs::path &dir, const std::string &source,
                               std::string *failure) {
  const char *compiler = LUTBAKE_TEST_CLANGXX;
  if (std::string(compiler).find("NOTFOUND") != std::string::npos) compiler = LUTBAKE_TEST_CXX;
  std::ofstream(dir / "main.cpp") << source;
  int status = 0;
  const std::string exe = (dir / "main").string();
  std::string out = RunCommand(std::string(compiler) + " -std=c++17 -Wall -Wextra -Werror -I'" +
                                   std::string(LUTBAKE_TEST_DATA) + "/../formats/metal_shim' '" +
                                   (dir / "main.cpp").string() + "' -o '" + exe + "' 2>&1",
                               &status);
  if (status != 0) {
    *failure = "compiling: " + out.substr(0, 6000);
    return "";
  }
  out = RunCommand("'" + exe + "'", &status);
  if (status != 0) {
    *failure = "running: " + out.substr(0, 6000);
    return "";
  }
  return out;
}

// The Metal code as C++ on the CPU (metal_shim/metal_stdlib): both the array
// lookup_T and the texture lookup lutbake_sample_T against the library's
// Lookup (the C++ header's convention) at every texel centre, half-way
// between centres and at random points, in and beyond the axis range.
// float32 arithmetic: 2e-6 allowed. A half-texel error moves values by half
// a texel step, over 1e-3 here.
TEST(ShaderCode, MetalCompilesAsCppAndLooksUpAsTheLibrary) {
  const char *compiler = LUTBAKE_TEST_CLANGXX;
  if (std::string(compiler).find("NOTFOUND") != std::string::npos) compiler = LUTBAKE_TEST_CXX;
  const fs::path dir = test::FormatTempDir("shader_msl");
  std::ostringstream main;
  main << EmittedCode(ShaderLanguage::kMsl, dir) << "#include <cstdio>\n"
       << "int main() {\n  float acc = 0.0f;\n";
  std::mt19937 random(7);
  std::vector<std::vector<double>> points;  // per call: table index, coordinates
  size_t index = 0;
  for (const Table &t : Tables()) {
    const std::string n = std::to_string(index);
    const std::vector<std::pair<int, int>> groups = ChannelGroups(t);
    for (size_t g = 0; g < groups.size(); ++g)
      main << MetalTexture(t, TextureName(index, g), groups[g].first, groups[g].second);
    if (t.channels > 4) {  // its lookups: MetalAreaLightAgreesWithTheLtcIntegral
      ++index;
      continue;
    }
    const Axis *axes[3] = {&t.x, &t.y, &t.z};
    const int dims = 1 + t.is2D() + t.is3D();
    // Centres and half-way points on each axis, then random points.
    std::vector<std::vector<double>> perAxis(static_cast<size_t>(dims));
    for (int a = 0; a < dims; ++a) {
      const Axis &axis = *axes[a];
      for (int i = 0; i < axis.count; ++i) {
        perAxis[a].push_back(axis.TexelCenter(i));
        if (i + 1 < axis.count)
          perAxis[a].push_back(0.5 * (axis.TexelCenter(i) + axis.TexelCenter(i + 1)));
      }
    }
    std::vector<std::vector<double>> mine;
    for (double x : perAxis[0])
      for (double y : dims > 1 ? perAxis[1] : std::vector<double>{0.0})
        for (double z : dims > 2 ? perAxis[2] : std::vector<double>{0.0}) mine.push_back({x, y, z});
    for (int k = 0; k < 64; ++k) {
      std::vector<double> p;
      for (int a = 0; a < 3; ++a) {
        const double span = axes[a]->max - axes[a]->min;
        p.push_back(axes[a]->min - 0.1 * span +
                    1.2 * span * std::uniform_real_distribution<double>(0, 1)(random));
      }
      mine.push_back(p);
    }
    for (const std::vector<double> &p : mine) {
      std::string args;
      for (int a = 0; a < dims; ++a) {
        args += std::string(a ? ", " : "") + FloatText(p[a]) + "f";
      }
      for (const char *kind : {"lookup", "sample"}) {
        const std::string call =
            std::string(kind) == "lookup"
                ? "lookup_" + t.Name() + "(" + args + ")"
                : "lutbake_sample_" + t.Name() + "(t" + n + ", t" + n + "_sampler, " + args + ")";
        for (int c = 0; c < t.channels; ++c)
          main << "  std::printf(\"%.9g\\n\", static_cast<double>(" << call
               << (t.channels > 1 ? std::string(".") + "xy"[c] : std::string()) << "));\n";
      }
      std::vector<double> q = {static_cast<double>(index)};
      for (int a = 0; a < 3; ++a) q.push_back(static_cast<float>(p[a]));
      points.push_back(q);
    }
    ++index;
  }
  // The fits' functions at random points, against the library's float32
  // evaluation (clang may fuse multiply-adds: 1e-5 allowed, above the
  // fits' a-priori rounding bounds for such a change).
  std::vector<std::pair<size_t, std::pair<double, double>>> fitPoints;
  for (size_t k = 0; k < Fits().size(); ++k)
    for (int i = 0; i < 64; ++i) {
      const double x = static_cast<float>(std::uniform_real_distribution<double>(0, 1)(random));
      const double y = static_cast<float>(std::uniform_real_distribution<double>(0, 1)(random));
      const FitSource &f = Fits()[k];
      const std::string call = "lutbake_fit_" + f.name + "(" + FloatText(x) + "f" +
                               (f.fit.dims == 2 ? ", " + FloatText(y) + "f" : "") + ")";
      for (int c = 0; c < f.fit.channels; ++c)
        main << "  std::printf(\"%.9g\\n\", static_cast<double>(" << call
             << (f.fit.channels > 1 ? std::string(".") + "xy"[c] : std::string()) << "));\n";
      fitPoints.push_back({k, {x, y}});
    }
  main << Calls(ShaderLanguage::kMsl)
       << "  std::printf(\"acc %g\\n\", static_cast<double>(acc));\n}\n";
  std::ofstream(dir / "main.cpp") << main.str();
  int status = 0;
  const std::string exe = (dir / "main").string();
  std::string out = RunCommand(std::string(compiler) + " -std=c++17 -Wall -Wextra -Werror -I'" +
                                   std::string(LUTBAKE_TEST_DATA) + "/../formats/metal_shim' '" +
                                   (dir / "main.cpp").string() + "' -o '" + exe + "' 2>&1",
                               &status);
  ASSERT_EQ(status, 0) << out.substr(0, 6000);
  out = RunCommand("'" + exe + "'", &status);
  ASSERT_EQ(status, 0) << out;
  std::istringstream lines(out);
  double worst = 0.0;
  for (const std::vector<double> &q : points) {
    const Table &t = Tables()[static_cast<size_t>(q[0])];
    for (int kind = 0; kind < 2; ++kind)
      for (int c = 0; c < t.channels; ++c) {
        double got = 0.0;
        ASSERT_TRUE(lines >> got);
        const double want =
            t.is3D() ? Lookup(t, t.values, q[1], q[2], q[3], c) : Lookup(t, q[1], q[2], c);
        worst = std::max(worst, std::abs(got - want));
        ASSERT_NEAR(got, want, 2e-6) << t.Name() << (kind ? " sample" : " lookup") << " at ("
                                     << q[1] << ", " << q[2] << ", " << q[3] << ") channel " << c;
      }
  }
  double worstFit = 0.0;
  for (const auto &[k, p] : fitPoints) {
    const FitSource &f = Fits()[k];
    for (int c = 0; c < f.fit.channels; ++c) {
      double got = 0.0;
      ASSERT_TRUE(lines >> got);
      const double want = f.fit.EvaluateFloat(c, p.first, p.second);
      worstFit = std::max(worstFit, std::abs(got - want));
      ASSERT_NEAR(got, want, 1e-5) << f.name << " fit at (" << p.first << ", " << p.second << ")";
    }
  }
  std::printf("MSL fits: %zu points, worst |shader - library| %.3g\n", fitPoints.size(), worstFit);
  std::string acc;
  lines >> acc;
  EXPECT_EQ(acc, "acc");
  std::printf("MSL lookups: %zu points, worst |shader - library| %.3g\n", points.size(), worst);
}

// A float3 literal in Metal.
std::string MetalFloat3(const std::array<float, 3> &v) {
  return "float3(" + FloatText(v[0]) + "f, " + FloatText(v[1]) + "f, " + FloatText(v[2]) + "f)";
}

// The area-light functions of ltc_ggx run as C++ in float32 (the shim)
// against the LTC integral in double over the same table (Lookup), within
// the derived float bound of support/ltc_area_light_reference.h: random
// rectangles (crossing the horizon, below it, either winding) at random
// (mu, r), each through lutbake_rect_light_ltc_ggx_f1 two- and one-sided,
// lutbake_rect_light_ltc_ggx (F0 = 0.04, F90 = 1) and
// lutbake_rect_light_diffuse; and the two texture lookups against Lookup.
TEST(ShaderCode, MetalAreaLightAgreesWithTheLtcIntegral) {
  const Table &ltc = Tables().back();
  ASSERT_EQ(ltc.Name(), "ltc_ggx");
  const fs::path dir = test::FormatTempDir("shader_msl_ltc");
  const fs::path code = dir / "lutbake.metal";
  WriteShaderCode(code.string(), ShaderLanguage::kMsl, {ltc}, {});
  std::ostringstream main;
  main << ReadText(code) << "#include <cstdio>\nint main() {\n"
       << MetalTexture(ltc, "m", 0, 4) << MetalTexture(ltc, "f", 4, 2);
  std::mt19937 random(28);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<std::array<double, 2>> points;
  for (int k = 0; k < 40; ++k) {
    const double mu = -0.1 + 1.2 * uniform(random), r = -0.1 + 1.2 * uniform(random);
    points.push_back({static_cast<float>(mu), static_cast<float>(r)});
    const std::string args = FloatText(mu) + "f, " + FloatText(r) + "f";
    main << "  { float4 a = lutbake_sample_ltc_ggx_ch0_3(m, m_sampler, " << args
         << ");\n    float2 b = lutbake_sample_ltc_ggx_ch4_5(f, f_sampler, " << args
         << ");\n    std::printf(\"%.9g %.9g %.9g %.9g %.9g %.9g\\n\", a.x, a.y, a.z, a.w, b.x, "
            "b.y); }\n";
  }
  std::vector<test::AreaLightCase> cases;
  for (int k = 0; k < 160; ++k) {
    const double mu = 0.02 + 0.975 * uniform(random), r = 0.05 + 0.95 * uniform(random);
    const std::array<Vec3, 4> local = test::RandomRectangle(random);
    cases.push_back(test::MakeCase(mu, r, local, test::RandomRotation(random)));
    const test::AreaLightCase &c = cases.back();
    std::string args = MetalFloat3(c.N) + ", " + MetalFloat3(c.V) + ", ";
    std::string corners;
    for (int i = 0; i < 4; ++i) corners += MetalFloat3(c.p[i]) + (i < 3 ? ", " : "");
    const std::string tables = "m, m_sampler, f, f_sampler, ";
    const std::string withR = args + FloatText(c.r) + "f, " + corners;
    main << "  std::printf(\"%.9g %.9g %.9g %.9g\\n\", lutbake_rect_light_ltc_ggx_f1(" << tables
         << withR << ", true),\n    lutbake_rect_light_ltc_ggx(" << tables << withR
         << ", float3(0.04f, 0.04f, 0.04f), float3(1.0f, 1.0f, 1.0f), true).x,\n"
         << "    lutbake_rect_light_diffuse(" << args << corners
         << ", true),\n    lutbake_rect_light_ltc_ggx_f1(" << tables << withR << ", false));\n";
  }
  main << "}\n";
  std::string failure;
  const std::string out = CompileAndRunMetal(dir, main.str(), &failure);
  ASSERT_FALSE(out.empty()) << failure;
  std::istringstream lines(out);
  for (const auto &p : points)
    for (int c = 0; c < 6; ++c) {
      double got = 0.0;
      ASSERT_TRUE(lines >> got);
      const double want = Lookup(ltc, p[0], p[1], c);
      ASSERT_NEAR(got, want, 2e-6 * std::max(1.0, std::abs(want)))
          << "channel " << c << " at (" << p[0] << ", " << p[1] << ")";
    }
  double worstRatio = 0.0, worstRelative = 0.0;
  int lit = 0, unlit = 0;
  for (const test::AreaLightCase &c : cases) {
    double got[4];
    for (double &g : got) ASSERT_TRUE(lines >> g);
    const test::AreaLightExpected e = test::ExpectedAreaLight(ltc, c, 0.04);
    const double want[4] = {e.f1, e.fresnel, e.diffuse, e.oneSided};
    const double bound[4] = {e.f1Bound, e.fresnelBound, e.diffuseBound, e.f1Bound};
    for (int k = 0; k < 4; ++k) {
      if (k == 3 && e.facingMargin < 1e-3) continue;  // nearly edge-on: the side is moot
      worstRatio = std::max(worstRatio, std::abs(got[k] - want[k]) / bound[k]);
      if (want[k] > 1e-3) worstRelative = std::max(worstRelative, std::abs(got[k] / want[k] - 1));
      EXPECT_LE(std::abs(got[k] - want[k]), bound[k])
          << "output " << k << " at mu = " << c.mu << ", r = " << c.r << ": shader " << got[k]
          << ", double " << want[k];
    }
    (e.oneSided > 0 ? lit : unlit) += e.integral > 0 ? 1 : 0;
  }
  EXPECT_GT(lit, 20);
  EXPECT_GT(unlit, 20);
  std::printf(
      "MSL area light: %zu cases (%d lit one-sided, %d facing away), worst |float - double| "
      "%.3g of its bound, worst relative %.3g (values > 1e-3)\n",
      cases.size(), lit, unlit, worstRatio, worstRelative);
}

}  // namespace
}  // namespace lutbake
