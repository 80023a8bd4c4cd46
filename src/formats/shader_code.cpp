// lutbake.glsl / .hlsl / .wgsl / .metal (--shader): the functions an engine
// needs to use a baked set, in its shading language. For every baked table
// T a texture lookup
//
//   lutbake_sample_T(texture[, sampler], x[, y[, z]])
//
// reads T's texture (T.png, T.ktx2, T.dds, T.exr or the data of T.js,
// uploaded as it is stored: width = x texels, height = y texels, channel c
// in component c, linear, no sRGB) with the table's exact convention. Texel
// i of an axis of N texels holds the value at u = (i + 0.5) / N over
// [min, max], which is exactly where a GPU's bilinear filter puts texel i's
// centre; so on a linear axis the texture coordinate is the axis value
// mapped onto [0, 1] with no further remap,
//   u = (v - min) / (max - min),
// clamped to [0.5 / N, 1 - 0.5 / N] (the first and last centres: the table
// clamps there, and the clamp does not depend on the sampler's wrap mode).
// A listed axis goes through its continuous texel coordinate t (linear in
// v between nodes): u = (t + 0.5) / N. A 3D table (glass_E) is read as the
// EXR, PNG and the modules store it: its depth slices stacked along y in one
// 2D texture of height H D; the lookup reads slices z0 and z0 + 1 at rows
// z H + t_y (t_y clamped to [0, H - 1], so the filter never mixes two
// slices) and interpolates between them in z. Bilinear filtering must be on
// (GL_LINEAR / D3D12_FILTER_MIN_MAG_MIP_LINEAR / "linear"), no mipmaps; its
// weights carry the hardware's sub-texel precision (8 bits on common GPUs).
//
// Then, only where their tables are in the set (decided by the tables'
// roles, never by name):
//   split sum (dfg):      lutbake_specular_albedo(AB, F0, F90) = F0 A + F90 B
//   F82 tint (dfg, f82):  lutbake_f82_tint_a(F0, tint), and
//                         lutbake_specular_albedo_f82(AB, C, F0, F90, a)
//                           = F0 A + F90 B - a C
//   Kulla-Conty (E, Eavg): lutbake_f_ms(E_o, E_i, Eavg), lutbake_fresnel_ms,
//                         lutbake_favg_schlick, lutbake_ms_albedo and
//                         lutbake_f_ms_E(...) from the textures
//   sheen (sheen_E):      lutbake_sheen_albedo_scaling(sheenColor, E[, E_l])
//   area lights (ltc_ggx): lutbake_rect_light_T(...) and _f1, the LTC integral
//                         of a rectangular light (ltc_area_light_code.cpp);
//                         a table of six channels is read as two textures,
//                         channels 0-3 (RGBA) and 4-5 (RG)
// with the formulas of the C++ headers (kulla_conty.h, f82.h, sheen_E.h).
#include <algorithm>
#include <sstream>

#include "file_io.h"
#include "ltc_area_light_code.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/tables/table_definition.h"
#include "source_text.h"

namespace lutbake {

namespace {

using namespace source_text;
using Params = std::vector<std::pair<std::string, std::string>>;

// The texture coordinate of axis value v on a 2D axis of N texels.
std::string TextureCoordinate(const Dialect &d, const Axis &axis, const std::string &v) {
  const int n = axis.count;
  if (n <= 1) return d.Lit(0.5);
  if (axis.listed())
    return "(" + TexelCoordinate(d, axis, v) + " + " + d.Lit(0.5) + ") * " + d.Lit(1.0 / n);
  return "clamp((" + v + " - " + d.Lit(axis.min) + ") * " + d.Lit(1.0 / (axis.max - axis.min)) +
         ", " + d.Lit(0.5 / n) + ", " + d.Lit(1.0 - 0.5 / n) + ")";
}

std::string AxisLine(const Axis &axis) {
  if (axis.listed()) return axis.name + " listed at " + std::to_string(axis.count) + " nodes";
  return axis.name + " in [" + FormatDouble(axis.min) + ", " + FormatDouble(axis.max) + "], " +
         std::to_string(axis.count) + " texels";
}

// The lookup of channels [first, first + c) of `table` in one texture; for
// a table of more than four channels (ltc_ggx: six) one per four channels,
// named lutbake_sample_T_ch<first>_<last> with texture T_ch<first>_<last>_texture.
std::string SampleFunction(const Dialect &d, const Table &table, int first, int c) {
  const std::string name = table.channels <= 4 ? table.Name()
                                               : table.Name() + "_ch" + std::to_string(first) +
                                                     "_" + std::to_string(first + c - 1);
  const std::string tex = name + "_texture";
  const std::string F = d.Float(), V = d.Float(c), F2 = d.Float(2);
  const std::vector<std::string> axes = AxisParams(table);
  Params params = d.TextureParams(tex);
  for (const std::string &p : axes) params.emplace_back(F, p);
  std::string body;
  std::string comment =
      "// " + name + " (" + table.definition->Summary() + ")\n//   x: " + AxisLine(table.x);
  if (table.is2D()) comment += "\n//   y: " + AxisLine(table.y);
  if (table.is3D()) comment += "\n//   z: " + AxisLine(table.z) + ", slices stacked along y";
  std::string channels;
  const std::vector<std::string> meanings = table.definition->ChannelMeanings();
  for (int i = 0; i < c && first + i < static_cast<int>(meanings.size()); ++i)
    channels += (i ? ", " : "") + std::string(1, "xyzw"[i]) + " = " + meanings[first + i];
  if (table.channels > 4)
    channels += " (channels " + std::to_string(first) + " to " + std::to_string(first + c - 1) +
                " of " + table.Name() + ", uploaded as this texture's components)";
  comment += "\n//   texture " + std::to_string(table.width()) + " x " +
             std::to_string(table.height() * table.depth()) + ", returns " + channels + "\n";
  body += d.Let(F, "u", TextureCoordinate(d, table.x, axes[0]));
  if (!table.is3D()) {
    body += d.Let(F, "v", table.is2D() ? TextureCoordinate(d, table.y, axes[1]) : d.Lit(0.5));
    body += "  return " + d.SampleLevel0(tex, d.Vec({"u", "v"})) + Swizzle(c) + ";\n";
    return comment + d.Function(V, "lutbake_sample_" + name, params, body);
  }
  const int h = table.height(), depth = table.depth();
  body += d.Let(F, "ty", TexelCoordinate(d, table.y, axes[1]));
  body += d.Let(F, "tz", TexelCoordinate(d, table.z, axes[2]));
  body += d.Let(d.Int(), "z0",
                "min(" + d.ToInt("tz") + ", " + std::to_string(depth > 1 ? depth - 2 : 0) + ")");
  body += d.Let(F, "wz", "tz - " + d.ToFloat("z0"));
  body += d.Let(d.Int(), "z1", "min(z0 + 1, " + std::to_string(depth - 1) + ")");
  const std::string rows = d.Lit(1.0 / (static_cast<double>(h) * depth));
  body +=
      d.Let(F, "v0",
            "(" + d.ToFloat("z0 * " + std::to_string(h)) + " + ty + " + d.Lit(0.5) + ") * " + rows);
  body +=
      d.Let(F, "v1",
            "(" + d.ToFloat("z1 * " + std::to_string(h)) + " + ty + " + d.Lit(0.5) + ") * " + rows);
  body += d.Let(V, "s0", d.SampleLevel0(tex, d.Vec({"u", "v0"})) + Swizzle(c));
  body += d.Let(V, "s1", d.SampleLevel0(tex, d.Vec({"u", "v1"})) + Swizzle(c));
  body += "  return s0 * (" + d.Lit(1.0) + " - wz) + s1 * wz;\n";
  return comment + d.Function(V, "lutbake_sample_" + name, params, body);
}

const TableDefinition *FindDefinition(const std::vector<Table> &tables, PlanRole role) {
  for (const Table &t : tables)
    if (t.definition && t.definition->Role() == role) return t.definition;
  return nullptr;
}

std::string Max3(const std::string &c) { return "max(max(" + c + ".x, " + c + ".y), " + c + ".z)"; }

}  // namespace

void WriteShaderCode(const std::string &path, ShaderLanguage language,
                     const std::vector<Table> &tables,
                     const std::vector<std::pair<std::string, std::string>> &metadata) {
  const Dialect d(language);
  const std::string F = d.Float(), F2 = d.Float(2), F3 = d.Float(3);
  std::ostringstream out;
  std::string names;
  for (const Table &t : tables) names += (names.empty() ? "" : ", ") + t.Name();
  WriteMetadataComment(out,
                       std::string("lutbake") + ShaderExtension(language) + ": " +
                           ToString(language) + " functions for the tables " + names +
                           ", generated by lutbake. Do not edit; regenerate.",
                       metadata);
  out << "// Texture lookups: lutbake_sample_T reads table T's texture, uploaded as stored\n"
         "// (width = x texels, height = y texels, or y texels times the z slices stacked\n"
         "// along y for a 3D table; channel c in component c; linear data, no sRGB), with\n"
         "// bilinear filtering and no mipmaps. Texel i of N holds the value at\n"
         "// u = (i + 0.5) / N over the axis range, where the GPU puts texel i's centre, so a\n"
         "// linear axis maps straight onto the texture coordinate,\n"
         "//   u = (v - min) / (max - min), clamped to [0.5 / N, 1 - 0.5 / N]\n"
         "// (no (N - 1) / N rescale: that is the convention of tables sampled at the\n"
         "// edges u = i / (N - 1), not lutbake's). mu are cosines to the normal (NdotV);\n"
         "// perceptualRoughness r is the artist's roughness, alpha = r^2.\n";
  if (language == ShaderLanguage::kGlsl)
    out << "// GLSL ES 3.00 (WebGL2) or 4.50: include after '#version' and\n"
           "// 'precision highp float;'.\n";
  out << "\n" << d.Prologue();
  for (const Table &t : tables)
    for (int first = 0; first < t.channels; first += 4)
      out << SampleFunction(d, t, first, std::min(4, t.channels - first));

  // Split sum.
  const TableDefinition *dfg = FindDefinition(tables, PlanRole::kImageBasedLighting);
  if (dfg) {
    out << "// Split-sum specular albedo (table " << dfg->Name()
        << ", AB = its lookup at (NdotV, r)): with Schlick's\n"
           "// Fresnel F = F0 + (F90 - F0) (1 - v.h)^5 the directional albedo is\n"
           "//   integral f F cos = F0 A + F90 B,\n"
           "// A = integral (f/F) (1 - (1 - v.h)^5) cos, B = integral (f/F) (1 - v.h)^5 cos.\n"
           "// Times the prefiltered radiance, the split-sum image-based specular.\n";
    out << d.Function(F3, "lutbake_specular_albedo", {{F2, "AB"}, {F3, "F0"}, {F3, "F90"}},
                      "  return F0 * AB.x + F90 * AB.y;\n");
  }
  if (dfg && FindDefinition(tables, PlanRole::kF82ImageBasedLighting)) {
    out << "// The F82-tint Fresnel of metals (Kutz et al. 2021; OpenPBR's metal):\n"
           "//   F(c) = F0 + (F90 - F0) (1 - c)^5 - a c (1 - c)^6,  c = v.h,\n"
           "// per colour channel, with\n"
           "//   a = Schlick(F0, 1/7) (1 - tint) / ((1/7) (1 - 1/7)^6),\n"
           "//   Schlick(F0, c) = F0 + (1 - F0) (1 - c)^5  (F90 = 1),\n"
           "// so that F(1/7) = tint Schlick(F0, 1/7); tint is the F82 tint in [0, 1].\n";
    const double y = 6.0 / 7.0, y5 = y * y * y * y * y, y6 = y5 * y;
    out << d.Function(
        F3, "lutbake_f82_tint_a", {{F3, "F0"}, {F3, "tint"}},
        d.Let(F3, "schlick",
              "F0 + (" + d.Vec({d.Lit(1.0), d.Lit(1.0), d.Lit(1.0)}) + " - F0) * " + d.Lit(y5)) +
            "  return schlick * (" + d.Vec({d.Lit(1.0), d.Lit(1.0), d.Lit(1.0)}) + " - tint) * " +
            d.Lit(7.0 / y6) + ";\n");
    out << "// Its specular albedo: F0 A + F90 B - a C, with A, B from dfg and C from f82 at\n"
           "// the same (NdotV, r).\n";
    out << d.Function(F3, "lutbake_specular_albedo_f82",
                      {{F2, "AB"}, {F, "C"}, {F3, "F0"}, {F3, "F90"}, {F3, "a"}},
                      "  return F0 * AB.x + F90 * AB.y - a * C;\n");
  }
  // Kulla-Conty: every average that declares it, with its table in the set.
  bool kullaContyCore = false;
  for (const Table &avg : tables) {
    if (!avg.definition) continue;
    const TableRelations relations = avg.definition->Relations();
    if (!relations.kullaConty) continue;
    const std::string suffix = avg.Name().substr(std::string(avg.definition->Name()).size());
    const auto of = std::find_if(tables.begin(), tables.end(), [&](const Table &t) {
      return t.definition && t.definition->Name() == relations.averageOf &&
             t.Name() == relations.averageOf + suffix;
    });
    if (of == tables.end()) continue;
    if (!kullaContyCore) {
      kullaContyCore = true;
      out << "// Kulla-Conty multiple scattering (Kulla and Conty 2017), as kulla_conty.h.\n"
             "// A single-scattering microfacet BRDF reflects E(mu_o, r) of the light (F = 1)\n"
             "// and loses 1 - E to paths that bounce between microfacets; the lobe\n"
             "//   f_ms(mu_o, mu_i, r) = (1 - E(mu_o, r)) (1 - E(mu_i, r)) / (pi (1 - E_avg(r))),\n"
             "// E_avg(r) = 2 integral_0^1 E(mu, r) mu dmu, gives that energy back:\n"
             "//   integral f_ms mu_i d(omega_i) = 1 - E(mu_o),\n"
             "// so f + f_ms passes the white furnace. 0 where E_avg rounds to 1 (the mirror).\n";
      out << d.Function(
          F, "lutbake_f_ms", {{F, "E_o"}, {F, "E_i"}, {F, "Eavg"}},
          d.Let(F, "lost", d.Lit(1.0) + " - Eavg") +
              d.Let(F, "lobe",
                    "max(" + d.Lit(1.0) + " - E_o, " + d.Lit(0.0) + ") * max(" + d.Lit(1.0) +
                        " - E_i, " + d.Lit(0.0) + ") / (" + d.Lit(3.14159265358979) +
                        " * max(lost, " + d.Lit(1e-30) + "))") +
              "  return " + d.Select("lost > " + d.Lit(0.0), "lobe", d.Lit(0.0)) + ";\n");
      out << "// The albedo of the lobe, integral f_ms cos over the hemisphere = 1 - E(mu_o):\n"
             "// under a constant environment L the lobe adds L F_ms (1 - E(mu_o)).\n";
      out << d.Function(F, "lutbake_ms_albedo", {{F, "E_o"}},
                        "  return max(" + d.Lit(1.0) + " - E_o, " + d.Lit(0.0) + ");\n");
      out << "// The Fresnel colour of the lobe, per channel: the light that leaves after any\n"
             "// number of bounces, each reflecting F_avg and escaping with E_avg,\n"
             "//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),\n"
             "// F_avg clamped to [0, 1] (the denominator is then at least E_avg > 0).\n";
      const std::string one3 = d.Vec({d.Lit(1.0), d.Lit(1.0), d.Lit(1.0)});
      out << d.Function(
          F3, "lutbake_fresnel_ms", {{F3, "Favg"}, {F, "Eavg"}},
          d.Let(F3, "f",
                "clamp(Favg, " + d.Vec({d.Lit(0.0), d.Lit(0.0), d.Lit(0.0)}) + ", " + one3 + ")") +
              d.Let(F3, "denominator", one3 + " - f * (" + d.Lit(1.0) + " - Eavg)") +
              "  return f * f * Eavg / max(denominator, " +
              d.Vec({d.Lit(1e-30), d.Lit(1e-30), d.Lit(1e-30)}) + ");\n");
      out << "// F_avg of Schlick's Fresnel, exactly: 2 integral_0^1 F(mu) mu dmu\n"
             "// = 20/21 F0 + 1/21 F90.\n";
      out << d.Function(
          F3, "lutbake_favg_schlick", {{F3, "F0"}, {F3, "F90"}},
          "  return F0 * " + d.Lit(20.0 / 21.0) + " + F90 * " + d.Lit(1.0 / 21.0) + ";\n");
    }
    // From the textures of this pair.
    Params params = d.TextureParams(of->Name() + "_texture");
    for (const auto &p : d.TextureParams(avg.Name() + "_texture")) params.push_back(p);
    params.insert(params.end(), {{F, "mu_o"}, {F, "mu_i"}, {F, "r"}});
    out << "// f_ms from the textures of " << of->Name() << " and " << avg.Name() << ".\n";
    const std::string e =
        "lutbake_sample_" + of->Name() + "(" + d.TextureArgs(of->Name() + "_texture");
    out << d.Function(F, "lutbake_f_ms_" + of->Name(), params,
                      "  return lutbake_f_ms(" + e + ", mu_o, r), " + e + ", mu_i, r),\n" +
                          "                      lutbake_sample_" + avg.Name() + "(" +
                          d.TextureArgs(avg.Name() + "_texture") + ", r));\n");
  }
  if (FindDefinition(tables, PlanRole::kSheenAlbedoScaling)) {
    out << "// glTF KHR_materials_sheen's albedo scaling of the layers under a sheen of\n"
           "// colour sheenColor: with the view's albedo E_v = sheen_E(NdotV, sheenRoughness),\n"
           "//   albedo_scaling = 1 - max3(sheenColor) E_v,\n"
           "// and with the light's E_l = sheen_E(NdotL, sheenRoughness) too (punctual lights),\n"
           "//   albedo_scaling = min(1 - max3(sheenColor) E_v, 1 - max3(sheenColor) E_l).\n"
           "// Shade sheenColor f_sheen + albedo_scaling f_base. Unclamped, as the extension\n"
           "// states it (E exceeds 1 at grazing views of smooth sheen).\n";
    out << d.Function(F, "lutbake_sheen_albedo_scaling", {{F3, "sheenColor"}, {F, "E_v"}},
                      "  return " + d.Lit(1.0) + " - " + Max3("sheenColor") + " * E_v;\n");
    out << d.Function(F, "lutbake_sheen_albedo_scaling2",
                      {{F3, "sheenColor"}, {F, "E_v"}, {F, "E_l"}},
                      "  return min(lutbake_sheen_albedo_scaling(sheenColor, E_v),\n"
                      "             lutbake_sheen_albedo_scaling(sheenColor, E_l));\n");
  }
  // Rectangular area lights: every six-channel LTC table in the set.
  bool ltcCore = false;
  for (const Table &t : tables) {
    if (!t.definition || t.definition->Role() != PlanRole::kAreaLights || t.channels != 6) continue;
    if (!ltcCore) out << LtcPolygonFunctions(d);
    ltcCore = true;
    out << LtcRectangleFunctions(d, t);
  }
  WriteWholeFile(path, out.str());
}

}  // namespace lutbake
