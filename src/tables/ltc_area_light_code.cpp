// Rectangular area lights with linearly transformed cosines (Heitz, Dupuy,
// Hill and Neubelt 2016), in the four shading languages.
//
// Frame. At a shading point with unit normal N and unit view V the LTC frame
// is T1 = normalize(V - N (N.V)), T2 = cross(N, T1), N (right-handed; V lies
// in the T1-N half-plane, as v = (sqrt(1 - mu^2), 0, mu) of the table). When
// V is within 1e-6 of N, T1 is any tangent: the lobe at mu = 1 is
// axisymmetric. A corner p (relative to the shading point) has the frame
// coordinates l = (p.T1, p.T2, p.N).
//
// The integral. The polygon P spanned by the four corners is clipped to the
// surface's upper half-space l.z >= 0 (light from below the surface does not
// reach it), transformed by M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
// (table channels m00, m20, m02, m22) and clipped to w.z >= 0, where the
// clamped cosine D_o vanishes: Sutherland-Hodgman, 4 -> at most 6 -> at
// most 9 vertices (each pass emits at most n + n/2 for n inputs, whatever the
// rounding does; a convex quad gives at most 5 and 6). Then, Lambert's vector
// form factor with the normalised vertices u_i,
//   I = sum_i theta_i (u_i x u_{i+1}).z / |u_i x u_{i+1}| / (2 pi),
//   theta_i = atan2(|u_i x u_{i+1}|, u_i . u_{i+1}),
// which is int_P D(l) dl up to its sign: the closed form of models/ltc.h
// (LtcPolygonIntegral), in float32. Written with atan2 rather than
// acos(u_i . u_{i+1}): for nearly parallel vertices acos loses half the
// digits (its derivative is infinite at 1) while atan2(s, c) / s tends to 1
// with float32's relative precision; no series or fitted approximation of
// theta / sin(theta) is used, so the edge term carries only the rounding of
// a few operations (~1e-7 relative). The division is by max(s, 1e-30): a
// zero-length edge (s = 0, theta = 0) adds 0.
//
// Sides. The sum is negative when the corners p0, p1, p2, p3 wind
// counter-clockwise seen from the shading point, i.e. when the point lies on
// the side of n_L = cross(p1 - p0, p3 - p0) (three.js's RectAreaLight
// convention: its light shines along that normal). One-sided: max(-I, 0);
// two-sided: |I|.
//
// Reflectance. The lobe f (n.l) is approximated by magnitude D(l) and a
// Schlick F = F0 + (F90 - F0) (1 - v.h)^5 by replacing magnitude with
//   F0 (magnitude - fresnel) + F90 fresnel
// (= F0 magnitude + (1 - F0) fresnel for F90 = 1), so a light of uniform
// radiance L gives the outgoing radiance L (F0 (magnitude - fresnel) + F90
// fresnel) I: lutbake_rect_light_T. With F = 1 (magnitude I):
// lutbake_rect_light_T_f1. A Lambertian surface of albedo rho: rho L times
// lutbake_rect_light_diffuse (M^-1 = identity: int_P (n.l) / pi dl).
#include "ltc_area_light_code.h"

namespace lutbake {

namespace {

using source_text::Dialect;
using Params = std::vector<std::pair<std::string, std::string>>;

// The few statements beyond Dialect's: mutable variables, local arrays and
// counted loops.
std::string Var(const Dialect &d, const std::string &type, const std::string &name,
                const std::string &init, const std::string &indent = "  ") {
  if (d.language() == ShaderLanguage::kWgsl)
    return indent + "var " + name + ": " + type + " = " + init + ";\n";
  return indent + type + " " + name + " = " + init + ";\n";
}

std::string LocalArray(const Dialect &d, const std::string &type, const std::string &name, int n) {
  if (d.language() == ShaderLanguage::kWgsl)
    return "  var " + name + ": array<" + type + ", " + std::to_string(n) + ">;\n";
  return "  " + type + " " + name + "[" + std::to_string(n) + "];\n";
}

std::string ForLoop(const Dialect &d, const std::string &i, const std::string &bound,
                    const std::string &body) {
  const std::string head =
      d.language() == ShaderLanguage::kWgsl
          ? "  for (var " + i + ": i32 = 0; " + i + " < " + bound + "; " + i + " = " + i +
                " + 1) {\n"
          : "  for (int " + i + " = 0; " + i + " < " + bound + "; ++" + i + ") {\n";
  return head + body + "  }\n";
}

std::string Atan2(const Dialect &d) {
  return d.language() == ShaderLanguage::kGlsl ? "atan" : "atan2";
}

// One Sutherland-Hodgman pass: the `count` vertices of `in` clipped to
// z >= 0 into `out` (count `outCount`, declared by the caller).
std::string ClipPass(const Dialect &d, const std::string &in, const std::string &count,
                     const std::string &out, const std::string &outCount) {
  const std::string F = d.Float(), F3 = d.Float(3), zero = d.Lit(0.0);
  std::string body;
  body += "  " + d.Let(F3, "a", in + "[i]");
  body += "  " + d.Let(F3, "b", in + "[(i + 1) % " + count + "]");
  body += "    if (a.z >= " + zero + ") {\n      " + out + "[" + outCount + "] = a;\n      " +
          outCount + " = " + outCount + " + 1;\n    }\n";
  body += "    if ((a.z >= " + zero + ") != (b.z >= " + zero + ")) {\n";
  body += "    " + d.Let(F, "t", "a.z / (a.z - b.z)");
  body += "      " + out + "[" + outCount +
          "] = " + d.Vec({"a.x + t * (b.x - a.x)", "a.y + t * (b.y - a.y)", zero}) + ";\n      " +
          outCount + " = " + outCount + " + 1;\n    }\n";
  return ForLoop(d, "i", count, body);
}

}  // namespace

std::string LtcPolygonFunctions(const Dialect &d) {
  const std::string F = d.Float(), F3 = d.Float(3), F4 = d.Float(4), I = d.Int();
  std::string out;
  out +=
      "// Rectangular area lights with linearly transformed cosines (Heitz et al. 2016).\n"
      "// The edge term of Lambert's vector form factor between directions a and b (any\n"
      "// length): theta (u_a x u_b).z / |u_a x u_b|, u = normalised, theta = the arc\n"
      "// angle by atan2 (accurate for nearly parallel edges, where acos is not; no\n"
      "// approximation of theta / sin(theta): float32 rounding only).\n";
  const std::string tiny = d.Lit(1e-30);
  out += d.Function(F, "lutbake_ltc_edge", {{F3, "a"}, {F3, "b"}},
                    d.Let(F3, "ua", "a / sqrt(max(dot(a, a), " + tiny + "))") +
                        d.Let(F3, "ub", "b / sqrt(max(dot(b, b), " + tiny + "))") +
                        d.Let(F3, "c", "cross(ua, ub)") + d.Let(F, "s", "length(c)") +
                        d.Let(F, "theta", Atan2(d) + "(s, dot(ua, ub))") +
                        "  return c.z * (theta / max(s, " + tiny + "));\n");
  out +=
      "// The signed integral over the polygon l0 l1 l2 l3 (frame coordinates: z along\n"
      "// the normal) of the LTC density D of minv = (m00, m20, m02, m22): clipped to\n"
      "// l.z >= 0, transformed by M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]],\n"
      "// clipped to w.z >= 0 (4 -> at most 6 -> at most 9 vertices), edge terms summed,\n"
      "// / (2 pi). Negative when the corners wind counter-clockwise seen from the point.\n";
  std::string body;
  body += LocalArray(d, F3, "q", 4);
  body += "  q[0] = l0;\n  q[1] = l1;\n  q[2] = l2;\n  q[3] = l3;\n";
  body += "  // The surface's horizon.\n";
  body += LocalArray(d, F3, "s", 6) + Var(d, I, "n", "0");
  body += ClipPass(d, "q", "4", "s", "n");
  body += "  // M^-1, normalised (clipping needs only the directions).\n";
  body += ForLoop(
      d, "i", "n",
      "  " + d.Let(F3, "v", "s[i]") + "  " +
          d.Let(F3, "w",
                d.Vec({"minv.x * v.x + minv.z * v.z", "v.y", "minv.y * v.x + minv.w * v.z"})) +
          "    s[i] = w / sqrt(max(dot(w, w), " + tiny + "));\n");
  body += "  // The cosine's horizon.\n";
  body += LocalArray(d, F3, "c", 9) + Var(d, I, "m", "0");
  body += ClipPass(d, "s", "n", "c", "m");
  body += Var(d, F, "sum", d.Lit(0.0));
  body += ForLoop(d, "i", "m", "    sum = sum + lutbake_ltc_edge(c[i], c[(i + 1) % m]);\n");
  body += "  return sum * " + d.Lit(0.5 / 3.14159265358979323846) + ";\n";
  out += d.Function(F, "lutbake_ltc_polygon",
                    {{F4, "minv"}, {F3, "l0"}, {F3, "l1"}, {F3, "l2"}, {F3, "l3"}}, body);

  out +=
      "// The form factor int_P D(l) dl of the rectangle p0 p1 p2 p3 (corners relative to\n"
      "// the shading point, in order around it) under the LTC minv, at unit normal N and\n"
      "// unit view V: frame T1 = normalize(V - N (N.V)) (any tangent when V is within\n"
      "// 1e-6 of N), T2 = cross(N, T1), N. One-sided lights shine along\n"
      "// cross(p1 - p0, p3 - p0) (three.js's RectAreaLight convention): max(-I, 0);\n"
      "// two-sided: |I|.\n";
  const std::string one = d.Lit(1.0), zero = d.Lit(0.0);
  std::string frame;
  frame += d.Let(F3, "t", "V - N * dot(N, V)");
  frame += d.Let(F, "len", "length(t)");
  frame += d.Let(
      F3, "helper",
      d.Select("abs(N.z) < " + d.Lit(0.9), d.Vec({zero, zero, one}), d.Vec({one, zero, zero})));
  frame += d.Let(F3, "tangent", "normalize(cross(N, helper))");
  frame +=
      d.Let(F3, "T1", d.Select("len > " + d.Lit(1e-6), "t / max(len, " + tiny + ")", "tangent"));
  frame += d.Let(F3, "T2", "cross(N, T1)");
  for (int k = 0; k < 4; ++k) {
    const std::string p = "p" + std::to_string(k);
    frame += d.Let(F3, "l" + std::to_string(k),
                   d.Vec({"dot(" + p + ", T1)", "dot(" + p + ", T2)", "dot(" + p + ", N)"}));
  }
  frame += d.Let(F, "integral", "lutbake_ltc_polygon(minv, l0, l1, l2, l3)");
  frame +=
      "  return " + d.Select("twoSided", "abs(integral)", "max(-integral, " + zero + ")") + ";\n";
  out += d.Function(F, "lutbake_ltc_rect_form_factor",
                    {{F4, "minv"},
                     {F3, "N"},
                     {F3, "V"},
                     {F3, "p0"},
                     {F3, "p1"},
                     {F3, "p2"},
                     {F3, "p3"},
                     {"bool", "twoSided"}},
                    frame);
  out +=
      "// A Lambertian surface: int_P (n.l) / pi dl (M^-1 = identity); times albedo and\n"
      "// the light's radiance.\n";
  out += d.Function(
      F, "lutbake_rect_light_diffuse",
      {{F3, "N"}, {F3, "V"}, {F3, "p0"}, {F3, "p1"}, {F3, "p2"}, {F3, "p3"}, {"bool", "twoSided"}},
      "  return lutbake_ltc_rect_form_factor(" + d.Vec({one, zero, zero, one}) +
          ", N, V, p0, p1, p2, p3, twoSided);\n");
  return out;
}

std::string LtcRectangleFunctions(const Dialect &d, const Table &ltc) {
  const std::string F = d.Float(), F2 = d.Float(2), F3 = d.Float(3), F4 = d.Float(4);
  const std::string name = ltc.Name(), matrix = name + "_ch0_3_texture",
                    moments = name + "_ch4_5_texture";
  Params params = d.TextureParams(matrix);
  for (const auto &p : d.TextureParams(moments)) params.push_back(p);
  params.insert(params.end(), {{F3, "N"},
                               {F3, "V"},
                               {F, "perceptualRoughness"},
                               {F3, "p0"},
                               {F3, "p1"},
                               {F3, "p2"},
                               {F3, "p3"}});
  std::string body;
  body += d.Let(F, "mu", "clamp(dot(N, V), " + d.Lit(0.0) + ", " + d.Lit(1.0) + ")");
  body += d.Let(
      F4, "minv",
      "lutbake_sample_" + name + "_ch0_3(" + d.TextureArgs(matrix) + ", mu, perceptualRoughness)");
  body += d.Let(
      F2, "moments",
      "lutbake_sample_" + name + "_ch4_5(" + d.TextureArgs(moments) + ", mu, perceptualRoughness)");
  body +=
      d.Let(F, "formFactor", "lutbake_ltc_rect_form_factor(minv, N, V, p0, p1, p2, p3, twoSided)");
  std::string out;
  out += "// A rectangular light of uniform radiance L on the specular lobe of table " + name +
         "\n// (its channels m00, m20, m02, m22 in " + matrix + " and magnitude, fresnel in\n// " +
         moments +
         "): the outgoing radiance is L times\n"
         "//   (F0 (magnitude - fresnel) + F90 fresnel) formFactor\n"
         "// (Schlick's F; F90 = 1: F0 magnitude + (1 - F0) fresnel), mu = clamp(N.V, 0, 1),\n"
         "// formFactor = lutbake_ltc_rect_form_factor.\n";
  Params withFresnel = params;
  withFresnel.insert(withFresnel.end(), {{F3, "F0"}, {F3, "F90"}, {"bool", "twoSided"}});
  out += d.Function(
      F3, "lutbake_rect_light_" + name, withFresnel,
      body + "  return (F0 * (moments.x - moments.y) + F90 * moments.y) * formFactor;\n");
  out += "// The same with F = 1: magnitude formFactor.\n";
  params.push_back({"bool", "twoSided"});
  out += d.Function(F, "lutbake_rect_light_" + name + "_f1", params,
                    body + "  return moments.x * formFactor;\n");
  return out;
}

}  // namespace lutbake
