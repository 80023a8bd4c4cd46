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
// Then the helpers of the tables in the set, each written by its table's
// definition beside its C++ header helpers (TableDefinition::ShaderHelpers:
// a helper that needs two tables only where both are baked):
//   split sum (dfg.cpp):  lutbake_specular_albedo(AB, F0, F90) = F0 A + F90 B
//   F82 tint (f82.cpp, with dfg): lutbake_f82_tint_a(F0, tint), and
//                         lutbake_specular_albedo_f82(AB, C, F0, F90, a)
//                           = F0 A + F90 B - a C
//   Kulla-Conty (Eavg.cpp, with E): lutbake_f_ms(E_o, E_i, Eavg),
//                         lutbake_fresnel_ms, lutbake_favg_schlick,
//                         lutbake_ms_albedo and lutbake_f_ms_E(...) from the
//                         textures
//   sheen (sheen_E.cpp):  lutbake_sheen_albedo_scaling(sheenColor, E[, E_l])
//   area lights (ltc_ggx.cpp): lutbake_rect_light_T(...) and _f1, the LTC
//                         integral of a rectangular light
//                         (tables/ltc_area_light_code.cpp); a table of six
//                         channels is read as two textures, channels 0-3
//                         (RGBA) and 4-5 (RG)
// with the formulas of the C++ headers (kulla_conty.h, f82.h, sheen_E.h).
#include <algorithm>
#include <set>
#include <sstream>

#include "file_io.h"
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

}  // namespace

void WriteShaderCode(const std::string &path, ShaderLanguage language,
                     const std::vector<Table> &tables,
                     const std::vector<std::pair<std::string, std::string>> &metadata) {
  const Dialect d(language);
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

  // The tables' own helpers (TableDefinition::ShaderHelpers), by order and
  // within one order in the set's order (a stable sort); a key written once.
  std::vector<ShaderPiece> pieces;
  for (const Table &t : tables) {
    if (!t.definition) continue;
    for (ShaderPiece &piece : t.definition->ShaderHelpers(d, t, tables))
      pieces.push_back(std::move(piece));
  }
  std::stable_sort(pieces.begin(), pieces.end(),
                   [](const ShaderPiece &a, const ShaderPiece &b) { return a.order < b.order; });
  std::set<std::string> written;
  for (const ShaderPiece &piece : pieces)
    if (written.insert(piece.key).second) out << piece.code;
  WriteWholeFile(path, out.str());
}

}  // namespace lutbake
